// Golden-image regression of the classic shadow map, one frame per step of the tutorial on the built-in
// `tutorial` and `tutorial-spot` scenes: a content hash (FNV-1a of the RGBA8 pixels) that must be bit-exact at
// 0, 1 and 2 threads. When a hash differs the test prints the new one to paste here after checking the image.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/frame/frame.h"
#include "scenes/builtin_scenes.h"

namespace {

uint64_t fnv1a(const raster::ColorTarget& c) {
  uint64_t h = 1469598103934665603ull;
  for (int y = 0; y < c.height(); ++y) {
    const uint8_t* row = c.row8(y);
    for (int x = 0; x < c.width() * 4; ++x) h = (h ^ row[x]) * 1099511628211ull;
  }
  return h;
}

// Debug aid: SHADOWLAB_GOLDEN_DUMP=dir writes each frame as a binary PPM (top row first) to look at.
void write_ppm(const raster::ColorTarget& c, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return;
  std::fprintf(f, "P6\n%d %d\n255\n", c.width(), c.height());
  for (int y = c.height() - 1; y >= 0; --y)
    for (int x = 0; x < c.width(); ++x) std::fwrite(c.row8(y) + 4 * x, 1, 3, f);
  std::fclose(f);
}

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
    {"no_bias", "tutorial", "hard", "none", false, 4, false, 0x154c117a84f424b4ull},
    {"constant", "tutorial", "hard", "constant", false, 4, false, 0xa35c7591a3bbd766ull},
    {"slope", "tutorial", "hard", "slope", false, 4, false, 0x7be71a0f660d4f42ull},
    {"back_faces", "tutorial", "hard", "slope", true, 4, false, 0x1b9360ca7515a1a6ull},
    {"offset", "tutorial", "hard", "offset", false, 4, false, 0x708ca6ba0c817304ull},
    {"normal", "tutorial", "hard", "normal", false, 4, false, 0x6f7df4900a502e3dull},
    {"pcf", "tutorial", "pcf", "slope", true, 4, false, 0x8ef54fbaaa6fa6cbull},
    {"poisson4", "tutorial", "poisson", "slope", true, 4, false, 0xde4ae1ddcad7a6a9ull},
    {"poisson16", "tutorial", "poisson", "slope", true, 16, false, 0x3f69bc56b1998d10ull},
    {"stratified", "tutorial", "stratified", "slope", true, 4, true, 0x9a92c88694086af7ull},
    {"rotated", "tutorial", "rotated", "slope", true, 16, true, 0xce02d5accb4ac93dull},
    {"early_bail", "tutorial", "early-bail", "slope", true, 16, false, 0x22626a89abbbe81full},
    {"spot", "tutorial-spot", "pcf", "slope", true, 4, false, 0x38a44f7f843b8ce2ull},
};

class Golden : public testing::TestWithParam<Step> {};

TEST_P(Golden, HashIsStableAcrossThreadCounts) {
  const Step& s = GetParam();
  const scenes::Scene scene = scenes::builtin_scene(s.scene);
  frame::FrameOptions o;
  o.width = 320;
  o.height = 180;
  o.filter = s.filter;
  o.bias = s.bias;
  o.cull_front = s.cull_front;
  o.poisson_taps = s.taps;
  o.pcf_taps = s.pcf_taps;
  o.shadow_size = 1024;
  uint64_t first = 0;
  for (int threads : {0, 1, 2}) {
    raster::Renderer r(threads);
    const frame::Frame f = frame::render_frame(scene, o, r);
    ASSERT_EQ(f.maps.size(), 1u);
    const uint64_t h = fnv1a(f.color);
    if (threads == 0) first = h;
    if (const char* dir = std::getenv("SHADOWLAB_GOLDEN_DUMP"); dir && threads == 0) write_ppm(f.color, std::string(dir) + "/" + s.name + ".ppm");
    EXPECT_EQ(h, first) << s.name << ": threads " << threads << " differ from threads 0";
  }
  if (first != s.expected) {
    std::printf("golden %s: new hash 0x%016llxull\n", s.name, static_cast<unsigned long long>(first));
    ADD_FAILURE() << s.name << ": hash 0x" << std::hex << first << " expected 0x" << s.expected;
  }
}

INSTANTIATE_TEST_SUITE_P(Tutorial, Golden, testing::ValuesIn(kSteps),
                         [](const testing::TestParamInfo<Step>& i) { return std::string(i.param.name); });

// Options the frame renderer must refuse, naming the option.
TEST(Frame, RejectsUnknownOptions) {
  const scenes::Scene scene = scenes::builtin_scene("tutorial");
  raster::Renderer r(0);
  frame::FrameOptions o;
  o.width = 32;
  o.height = 32;
  o.filter = "blurry";
  EXPECT_THROW(frame::render_frame(scene, o, r), std::invalid_argument);
  o.filter.reset();
  o.bias = "huge";
  EXPECT_THROW(frame::render_frame(scene, o, r), std::invalid_argument);
  o.bias.reset();
  o.shadow_size = 3;
  EXPECT_THROW(frame::render_frame(scene, o, r), std::invalid_argument);
}

// The EXR map carries what CONVENTIONS asks for.
TEST(Frame, MapsCarryMatricesAndNames) {
  const scenes::Scene scene = scenes::builtin_scene("tutorial-spot");
  raster::Renderer r(0);
  frame::FrameOptions o;
  o.width = 64;
  o.height = 36;
  o.shadow_size = 256;
  const frame::Frame f = frame::render_frame(scene, o, r);
  ASSERT_EQ(f.maps.size(), 1u);
  EXPECT_EQ(f.maps[0].width, 256);
  EXPECT_EQ(f.maps[0].technique, "shadowmap");
  EXPECT_EQ(f.maps[0].depth_format, "d16");
  EXPECT_EQ(f.maps[0].encoding, "window-depth");
  EXPECT_NE(f.maps[0].world_to_ndc, glm::mat4(1.0f));
  EXPECT_EQ(f.map_names[0].rfind("light0-", 0), 0u);
  EXPECT_EQ(f.stats.maps_rendered, 1u);
}

}  // namespace
