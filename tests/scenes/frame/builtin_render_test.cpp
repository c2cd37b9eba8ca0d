// Every built-in scene renders through the frame renderer: a frame that is not just the clear colour, finite,
// with a shadow map for every light using the classic technique, and one map (one EXR) for every point or
// hemispherical light using cube, paraboloid or pyramid.
#include <gtest/gtest.h>

#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "tests/support.h"

TEST(BuiltinRender, EveryBuiltinSceneRenders) {
  raster::Renderer renderer(testsupport::test_threads());
  for (const auto& info : scenes::list_builtin_scenes()) {
    const scenes::Scene scene = scenes::builtin_scene(info.name);
    frame::FrameConfig opt;
    opt.width = 160, opt.height = 90;
    opt.map_size = 256;
    const frame::Frame f = frame::render_frame(scene, opt, renderer);
    ASSERT_EQ(f.color.width(), 160) << info.name;
    const glm::vec4 clear = f.color.read(0, 0);
    int differ = 0;
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 160; ++x) differ += f.color.read(x, y) != clear;
    EXPECT_GT(differ, 160 * 90 / 10) << info.name << ": the scene should fill part of the frame";
    const std::vector<frame::NamedMap> maps = frame::export_maps(f);
    for (const auto& m : maps) EXPECT_EQ(m.map.z.size(), size_t(m.map.width) * size_t(m.map.height)) << info.name;
    bool has_shadowed_light = false;
    for (const auto& l : scene.lights)
      has_shadowed_light |= l.shadow.technique == scenes::ShadowTechnique::shadowmap &&
                            (l.type == scenes::LightType::directional || l.type == scenes::LightType::spot);
    if (has_shadowed_light) {
      EXPECT_FALSE(maps.empty()) << info.name;
    }
    size_t omni = 0;
    for (const auto& l : scene.lights) {
      const auto t = l.shadow.technique;
      const bool omni_technique = t == scenes::ShadowTechnique::cube || t == scenes::ShadowTechnique::paraboloid ||
                                  t == scenes::ShadowTechnique::pyramid;
      omni += omni_technique && (l.type == scenes::LightType::point || l.type == scenes::LightType::hemispherical);
    }
    size_t omni_maps = 0;
    for (const auto& m : maps) omni_maps += m.map.encoding == "radial-distance";
    EXPECT_EQ(omni_maps, omni) << info.name << ": every omnidirectional light has its map";
  }
}
