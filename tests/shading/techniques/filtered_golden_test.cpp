// Golden-image regression of the filterable maps and PCSS on the built-in `tutorial` scene, lit by its sun and
// by a spot light over the room (the built-in `tutorial-spot` frame is lit by its spot nowhere the camera sees): one content hash per technique that must be the same at 0, 1 and 2 threads (the
// encode and blur passes are pipeline draws, the PCSS disc turns per pixel). New hashes are pasted here after
// looking at the image (SHADOWLAB_GOLDEN_DUMP=dir).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include <glm/geometric.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "tests/scenes/frame/golden.h"

namespace {

struct Case {
  const char* name;
  bool spot;
  const char* technique;
  uint64_t expected;
};

// 320 × 180 frames with 512² maps and each technique's defaults.
const Case kCases[] = {
    {"esm", false, "esm", 0xea5ae8db2c88df32ull},
    {"vsm", false, "vsm", 0xacc89ce09918d124ull},
    {"evsm2", false, "evsm2", 0x7f2d76d92e074a6cull},
    {"evsm4", false, "evsm4", 0x34cd1e137cbc6a91ull},
    {"pcss", false, "pcss", 0x308a6eeaf3bf43baull},
    {"esm_spot", true, "esm", 0x0a471c9b539af510ull},
    {"vsm_spot", true, "vsm", 0x9161fa5a8233cd4eull},
    {"evsm4_spot", true, "evsm4", 0xddd4b131a77ce007ull},
    {"pcss_spot", true, "pcss", 0x4d75c755a5cb9304ull},
};

// The tutorial room with its sun replaced by a spot light above the front of the room, aimed at the sphere.
scenes::Scene scene_for(bool spot) {
  scenes::Scene s = scenes::builtin_scene("tutorial");
  if (spot) {
    scenes::Light& l = s.lights.at(0);
    l.type = shading::tech::LightType::spot;
    l.position = {3.0f, 9.0f, 6.0f};
    l.direction = glm::normalize(glm::vec3(1.5f, 1.0f, 0.0f) - l.position);
    l.inner_cone_deg = 40.0f;
    l.outer_cone_deg = 50.0f;
    l.range = 30.0f;
    l.intensity = 80.0f;  // inverse-square falloff over about 9 m
  }
  return s;
}

class FilteredGolden : public testing::TestWithParam<Case> {};

TEST_P(FilteredGolden, HashIsStableAcrossThreadCounts) {
  const Case& c = GetParam();
  frame::FrameConfig o;
  o.width = 320;
  o.height = 180;
  o.technique = *shading::tech::parse_technique(c.technique);
  o.map_size = 512;
  testsupport::expect_golden_frame(c.name, c.expected, scene_for(c.spot), o,
                                   [](const frame::Frame& f) { ASSERT_EQ(frame::export_maps(f).size(), 1u); });
}

INSTANTIATE_TEST_SUITE_P(Techniques, FilteredGolden, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

}  // namespace
