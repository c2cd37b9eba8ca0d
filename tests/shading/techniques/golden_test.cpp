// Golden-image regression of the classic shadow map, one frame per step of the tutorial on the built-in
// `tutorial` and `tutorial-spot` scenes: a content hash (FNV-1a of the RGBA8 pixels) that must be bit-exact at
// 0, 1 and 2 threads. When a hash differs the test prints the new one to paste here after checking the image.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "tests/scenes/frame/golden.h"

namespace {

struct Step {
  const char* name;
  const char* scene;
  const char* filter;
  const char* bias;
  bool cull_front;
  int taps;
  bool pcf_taps;
  uint64_t expected;
};

// Expected hashes at 320 × 180 with 1024² d16 maps.
const Step kSteps[] = {
    {"no_bias", "tutorial", "hard", "none", false, 4, false, 0x5d72bd07abec54afull},
    {"constant", "tutorial", "hard", "constant", false, 4, false, 0x8f1a25b3c191d1beull},
    {"slope", "tutorial", "hard", "slope", false, 4, false, 0xda7cf99125908eacull},
    {"back_faces", "tutorial", "hard", "slope", true, 4, false, 0x86550efb7fbdc051ull},
    {"offset", "tutorial", "hard", "offset", false, 4, false, 0xa92ac965a83173bfull},
    {"normal", "tutorial", "hard", "normal", false, 4, false, 0x9083d1767ff2d911ull},
    {"pcf", "tutorial", "pcf", "slope", true, 4, false, 0x14ecacf3db01dd2cull},
    {"poisson4", "tutorial", "poisson", "slope", true, 4, false, 0x16d4d45005299e8aull},
    {"poisson16", "tutorial", "poisson", "slope", true, 16, false, 0x029d31672ed8e818ull},
    {"stratified", "tutorial", "stratified", "slope", true, 4, true, 0x23c3b71c7f77bba4ull},
    {"rotated", "tutorial", "rotated", "slope", true, 16, true, 0x10bf83ac6301bbe6ull},
    {"early_bail", "tutorial", "early-bail", "slope", true, 16, false, 0xd220bc784895ae3dull},
    {"spot", "tutorial-spot", "pcf", "slope", true, 4, false, 0xfcc10905a23e405dull},
};

class Golden : public testing::TestWithParam<Step> {};

TEST_P(Golden, HashIsStableAcrossThreadCounts) {
  const Step& s = GetParam();
  const scenes::Scene scene = scenes::builtin_scene(s.scene);
  frame::FrameConfig o;
  o.width = 320;
  o.height = 180;
  o.filter = *shading::tech::parse_filter(s.filter);
  o.bias = *shading::tech::parse_bias_mode(s.bias);
  o.cull_front = s.cull_front;
  o.poisson_taps = s.taps;
  o.params["pcf_taps"] = bool(s.pcf_taps);
  o.map_size = 1024;
  testsupport::expect_golden_frame(s.name, s.expected, scene, o,
                                   [](const frame::Frame& f) { ASSERT_EQ(frame::export_maps(f).size(), 1u); });
}

INSTANTIATE_TEST_SUITE_P(Tutorial, Golden, testing::ValuesIn(kSteps),
                         [](const testing::TestParamInfo<Step>& i) { return std::string(i.param.name); });

// Settings the frame renderer must refuse, naming the field (unknown names cannot reach a typed FrameConfig:
// the CLI refuses them, tests/cli/cli_test.cpp).
TEST(Frame, RejectsBadSettings) {
  const scenes::Scene scene = scenes::builtin_scene("tutorial");
  raster::Renderer r(0);
  frame::FrameConfig o;
  o.width = 32;
  o.height = 32;
  auto message = [&] {
    try {
      frame::render_frame(scene, o, r);
    } catch (const frame::FrameError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  o.map_size = 3;
  EXPECT_EQ(message().rfind("map_size: ", 0), 0u);
  o.map_size.reset();
  o.params["fit"] = std::string("loose");
  EXPECT_EQ(message().rfind("params.fit: ", 0), 0u) << message();
  o.params.clear();
  o.params["seamless"] = false;  // a cube parameter, and the tutorial has no cube light
  EXPECT_EQ(message().rfind("params.seamless: ", 0), 0u) << message();
  o.params.clear();
  EXPECT_EQ(message(), "no error");
}

// The EXR map carries what CONVENTIONS asks for.
TEST(Frame, MapsCarryMatricesAndNames) {
  const scenes::Scene scene = scenes::builtin_scene("tutorial-spot");
  raster::Renderer r(0);
  frame::FrameConfig o;
  o.width = 64;
  o.height = 36;
  o.map_size = 256;
  const frame::Frame f = frame::render_frame(scene, o, r);
  const std::vector<frame::NamedMap> maps = frame::export_maps(f);
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_EQ(maps[0].map.width, 256);
  EXPECT_EQ(maps[0].map.technique, "shadowmap");
  EXPECT_EQ(maps[0].map.depth_format, "d16");
  EXPECT_EQ(maps[0].map.encoding, "window-depth");
  EXPECT_NE(maps[0].map.world_to_ndc, glm::mat4(1.0f));
  EXPECT_EQ(maps[0].name.rfind("light0-", 0), 0u);
  EXPECT_EQ(f.stats.maps_rendered, 1u);
}

}  // namespace
