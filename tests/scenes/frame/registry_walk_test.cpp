// The registry walk: every technique of the vocabulary's table, against every light type. A built technique
// renders every light type it claims (a frame whose shadow differs from the unshadowed one, and its maps
// exported where it has any); every other combination — a type it does not claim, or a technique not built
// yet — is refused: by the frame library (FrameError), by the JSON loader (SceneError naming
// lights[0].shadow.technique) and by the command line (exit 2, one error line, no output file), whether the
// technique comes from the scene file or from --technique.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scenes/frame/frame.h"
#include "scenes/scene_build.h"
#include "scenes/scene_error.h"
#include "scenes/scene_json.h"
#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace tech = shading::tech;

// A floor, a pillar that casts onto it, a camera looking at both, and one light of `type` above them. The
// directional and spot lights stand behind the pillar as the camera sees it, so its shadow falls towards the
// camera, in view (from the other side it fell behind the pillar, and only acne told shadowed frames from
// unshadowed ones: techniques without acne, such as the filterable maps, drew no visible shadow).
std::string scene_json(tech::LightType type, std::string_view technique) {
  std::string light;
  switch (type) {
    case tech::LightType::directional: light = R"("type": "directional", "to_light": [-0.5, 2, -1])"; break;
    case tech::LightType::spot:
      light = R"("type": "spot", "position": [-3, 9, -3], "direction": [3, -9, 3], "inner_cone": 30, "outer_cone": 40, "range": 30)";
      break;
    case tech::LightType::point: light = R"("type": "point", "position": [2.5, 4, 1], "range": 20)"; break;
    case tech::LightType::hemispherical:
      light = R"("type": "hemispherical", "position": [2.5, 4, 1], "direction": [0, -1, 0], "range": 20)";
      break;
  }
  return R"({"version": 1, "name": "walk", "objects": [
    {"name": "floor", "primitive": {"type": "box", "size": [12, 0.5, 12]}, "transform": {"translate": [0, -0.25, 0]}},
    {"name": "pillar", "primitive": {"type": "box", "size": [1, 3, 1]}, "transform": {"translate": [0, 1.5, 0]}}],
  "cameras": [{"position": [6, 7, 9], "target": [0, 0.5, 0], "perspective": {"fovy": 50, "near": 0.5, "far": 60}}],
  "lights": [{"name": "l", )" + light + R"(, "shadow": {"technique": ")" + std::string(technique) + R"(", "map_size": 64}}]})";
}

scenes::Scene with_technique(tech::LightType type, tech::Technique t) {
  scenes::Scene s = scenes::build_scene(scenes::parse_scene_json(scene_json(type, "none"), "walk.json"));
  s.lights.at(0).shadow.technique = t;
  // 256²: a 64² map's texel (19 cm) under a 5×5 blur spreads the 1 m pillar's shadow over 1 m of lit floor,
  // and ESM's exp(c·z) average is then ruled by the floor behind it, which is farther from the light: no shadow.
  s.lights.at(0).shadow.map_size = 256;
  return s;
}

size_t pixels_differing(const raster::ColorTarget& a, const raster::ColorTarget& b) {
  size_t n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) n += a.read(x, y) != b.read(x, y);
  return n;
}

constexpr tech::LightType kLightTypes[] = {tech::LightType::directional, tech::LightType::spot, tech::LightType::point,
                                           tech::LightType::hemispherical};

}  // namespace

TEST(RegistryWalk, EveryBuiltTechniqueHasOneImplementationAndNoOtherDoes) {
  for (const tech::TechniqueInfo& t : tech::kTechniques) {
    size_t rows = 0;
    for (const tech::TechniqueImpl& i : tech::registry()) rows += i.id == t.id;
    EXPECT_EQ(rows, t.built ? 1u : 0u) << t.name;
    if (const tech::TechniqueImpl* i = tech::find_impl(t.id)) {
      EXPECT_EQ(i->plan != nullptr, i->application == tech::Application::light_visibility) << t.name;
    }
  }
}

TEST(RegistryWalk, EveryClaimedLightTypeRenders) {
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig config;
  config.width = 96, config.height = 54;
  for (tech::LightType type : kLightTypes) {
    config.exposure.reset();
    const frame::Frame unshadowed = frame::render_frame(with_technique(type, tech::Technique::none), config, renderer);
    // The unshadowed frame's metered exposure for both: metering each would move every pixel with the shadow.
    config.exposure = scenes::Exposure{unshadowed.ev100};
    for (const tech::TechniqueInfo& t : tech::kTechniques) {
      if (!t.built || !tech::supports(t.id, type) || t.id == tech::Technique::none) continue;
      SCOPED_TRACE(std::string(t.name) + " on a " + std::string(tech::to_string(type)) + " light");
      const frame::Frame f = frame::render_frame(with_technique(type, t.id), config, renderer);
      EXPECT_GT(pixels_differing(f.color, unshadowed.color), 20u) << "no shadow drawn";
      const std::vector<frame::NamedMap> maps = frame::export_maps(f);
      // A technique without a map (an empty encoding: irregular) exports none; every other one exports some.
      EXPECT_EQ(maps.empty(), t.encoding.empty());
      for (const frame::NamedMap& m : maps) {
        EXPECT_EQ(m.map.technique, t.name);
        EXPECT_EQ(m.map.encoding, t.encoding);
        EXPECT_EQ(m.map.z.size(), size_t(m.map.width) * size_t(m.map.height));
      }
    }
  }
}

TEST(RegistryWalk, EveryOtherCombinationIsRefusedEverywhere) {
  raster::Renderer renderer(0);
  const std::filesystem::path dir = testsupport::temp_dir("registry_walk");
  size_t refused = 0;
  for (tech::LightType type : kLightTypes) {
    for (const tech::TechniqueInfo& t : tech::kTechniques) {
      if (t.built && tech::supports(t.id, type)) continue;
      ++refused;
      const std::string combo = std::string(t.name) + " on a " + std::string(tech::to_string(type)) + " light";
      SCOPED_TRACE(combo);
      // The frame library, whether the scene or the configuration names the technique.
      EXPECT_THROW(frame::render_frame(with_technique(type, t.id), frame::FrameConfig{}, renderer), frame::FrameError);
      frame::FrameConfig override_config;
      override_config.technique = t.id;
      EXPECT_THROW(frame::render_frame(with_technique(type, tech::Technique::none), override_config, renderer),
                   frame::FrameError);
      // The JSON loader.
      const std::string text = scene_json(type, t.name);
      try {
        scenes::build_scene(scenes::parse_scene_json(text, "walk.json"));
        ADD_FAILURE() << "the JSON loader accepted it";
      } catch (const scenes::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("lights[0].shadow.technique"), std::string::npos) << e.what();
      }
      // The command line: from the file, and from --technique on an accepted file.
      std::ofstream(dir / "bad.json") << text;
      std::ofstream(dir / "good.json") << scene_json(type, "none");
      testsupport::expect_bad_run(dir, "render bad.json --size 32x18 --out out.png", "bad.json", "out.png");
      testsupport::expect_bad_run(dir, "render good.json --size 32x18 --out out.png --technique " + std::string(t.name),
                                  "--technique", "out.png");
    }
  }
  EXPECT_GE(refused, 16u);  // 4 light types × 3 unbuilt techniques, plus every type a built one does not claim
}
