// Golden images of the omnidirectional techniques: the built-in `pyramid` (hemispherical ceiling lamp) and
// `paraboloid` (point light among pillars) scenes with each of cube, paraboloid and pyramid, as content hashes
// (FNV-1a of the RGBA8 pixels) that must be bit-exact at 0, 1 and 2 threads. When a hash differs the test
// prints the new one to paste here after checking the image (SHADOWLAB_GOLDEN_DUMP=dir writes PPMs).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "tests/scenes/frame/golden.h"

namespace {

struct Case {
  const char* name;
  const char* scene;
  const char* technique;
  const char* filter;
  const char* pack;  // paraboloid depth packing, or null
  uint64_t expected;
};

// 320 × 180, 512² maps (per face for the cube), slope bias, the scenes' d24.
const Case kCases[] = {
    {"pyramid_scene_cube", "pyramid", "cube", "pcf", nullptr, 0x8181f9ca7e1b5a58ull},
    {"pyramid_scene_paraboloid", "pyramid", "paraboloid", "pcf", nullptr, 0x4838a354916046b0ull},
    {"pyramid_scene_pyramid", "pyramid", "pyramid", "pcf", nullptr, 0x20c734ecb225de77ull},
    {"pyramid_scene_pyramid_poisson", "pyramid", "pyramid", "rotated", nullptr, 0xcba61a910338baacull},
    {"paraboloid_scene_cube", "paraboloid", "cube", "pcf", nullptr, 0xe9e00ca0006721c5ull},
    {"paraboloid_scene_paraboloid", "paraboloid", "paraboloid", "pcf", nullptr, 0x6c535fc74920d0ecull},
    {"paraboloid_scene_paraboloid_rgba8", "paraboloid", "paraboloid", "hard", "rgba8", 0x7c36b9417ca96f17ull},
};

class OmniGolden : public testing::TestWithParam<Case> {};

TEST_P(OmniGolden, HashIsStableAcrossThreadCounts) {
  const Case& c = GetParam();
  const scenes::Scene scene = scenes::builtin_scene(c.scene);
  frame::FrameConfig o;
  o.width = 320;
  o.height = 180;
  o.technique = *shading::tech::parse_technique(c.technique);
  o.filter = *shading::tech::parse_filter(c.filter);
  o.map_size = 512;
  if (c.pack) o.params["paraboloid_pack"] = std::string(c.pack);
  testsupport::expect_golden_frame(c.name, c.expected, scene, o, [](const frame::Frame& f) {
    ASSERT_EQ(frame::export_maps(f).size(), 1u);
  });
}

// A pyramid map covers the 180° a hemispherical light lights; a point light lights all around, so the
// combination is refused (before the technique layer, the frame drew it with the back half unshadowed while
// the scene loader refused it).
TEST(OmniFrame, PyramidRefusesAPointLight) {
  raster::Renderer r(0);
  frame::FrameConfig o;
  o.width = 64, o.height = 36;
  o.technique = shading::tech::Technique::pyramid;
  try {
    frame::render_frame(scenes::builtin_scene("paraboloid"), o, r);
    ADD_FAILURE() << "accepted";
  } catch (const frame::FrameError& e) {
    EXPECT_EQ(std::string(e.what()), "technique: technique pyramid does not serve point lights (it serves: hemispherical)");
  }
}

INSTANTIATE_TEST_SUITE_P(Omni, OmniGolden, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// The EXR of each technique: one image with every pass's viewport and matrices, radial-distance encoding.
TEST(OmniFrame, MapsCarryEveryPass) {
  raster::Renderer r(0);
  frame::FrameConfig o;
  o.width = 64;
  o.height = 36;
  o.map_size = 64;
  struct Want {
    const char* scene;  // a point light, except the pyramid's hemispherical one
    const char* technique;
    int w, h;
    size_t passes;
  };
  for (const Want& w : {Want{"paraboloid", "cube", 192, 128, 6}, Want{"paraboloid", "paraboloid", 128, 64, 2},
                        Want{"pyramid", "pyramid", 64, 64, 4}}) {
    const scenes::Scene scene = scenes::builtin_scene(w.scene);
    o.technique = *shading::tech::parse_technique(w.technique);
    const frame::Frame f = frame::render_frame(scene, o, r);
    const std::vector<frame::NamedMap> maps = frame::export_maps(f);
    ASSERT_EQ(maps.size(), 1u);
    const scenes::io::ExrMap& m = maps[0].map;
    EXPECT_EQ(m.technique, w.technique);
    EXPECT_EQ(m.encoding, "radial-distance");
    EXPECT_EQ(m.width, w.w);
    EXPECT_EQ(m.height, w.h);
    ASSERT_EQ(m.passes.size(), w.passes);
    for (const auto& p : m.passes) {
      EXPECT_GT(p.viewport.width, 0);
      EXPECT_LE(p.viewport.x + p.viewport.width, m.width);
      EXPECT_LE(p.viewport.y + p.viewport.height, m.height);
    }
  }
}

// Options of the omni techniques that the frame renderer refuses, naming the option.
TEST(OmniFrame, RejectsBadOptions) {
  const scenes::Scene scene = scenes::builtin_scene("pyramid");
  raster::Renderer r(0);
  frame::FrameConfig o;
  o.width = 64;
  o.height = 36;
  o.map_size = 32;
  auto message = [&](frame::FrameConfig opt) -> std::string {
    try {
      frame::render_frame(scene, opt, r);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  frame::FrameConfig a = o;
  a.technique = *shading::tech::parse_technique("paraboloid");
  a.params["paraboloid_pack"] = std::string("rgb565");
  EXPECT_NE(message(a).find("params.paraboloid_pack"), std::string::npos);
  a.params.erase("paraboloid_pack");
  a.params["split_plane"] = std::string("0,0,0");
  EXPECT_NE(message(a).find("params.split_plane"), std::string::npos);
  a.params["split_plane"] = std::string("w");
  EXPECT_NE(message(a).find("params.split_plane"), std::string::npos);
  a.params["split_plane"] = std::string("1,0.5,0");  // a plane, but the pyramid scene's lamp is hemispherical
  EXPECT_EQ(message(a).rfind("params.split_plane: divides a point light's two paraboloids", 0), 0u) << message(a);
  a.params.erase("split_plane");
  EXPECT_EQ(message(a), "");
  frame::FrameConfig b = o;
  b.technique = *shading::tech::parse_technique("pyramid");
  b.map_size = 33;
  EXPECT_NE(message(b).find("map_size"), std::string::npos);
  b.map_size = 32;
  b.bias = *shading::tech::parse_bias_mode("offset");
  EXPECT_NE(message(b).find("bias"), std::string::npos);
}

}  // namespace
