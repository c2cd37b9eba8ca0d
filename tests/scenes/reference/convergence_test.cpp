// Shadow maps converge on the exact shadow as they grow: a classic map of 8192² on a box standing on a floor
// scores false-shadowed + false-lit below 0.5 % of the lit-facing pixels (the reference and the rasterizer agree
// about the geometry), and the error grows as the map shrinks. Also the surface record itself: on the floor, the
// recorded position and normal are the floor's, and the record is the same on both fragment paths and at any
// thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/frame/frame.h"
#include "scenes/reference/frame_reference.h"
#include "tests/scenes/reference/analytic_scenes.h"
#include "tests/support.h"

namespace {

// A 6 x 6 m floor and a 1 m box standing on it, the sun from the side and above, a camera at an angle.
const char* kBoxOnFloor = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [6, 6]}},
    {"name": "box", "primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}
  ],
  "cameras": [{"position": [3, 5, 6], "target": [0, 0, 0]}],
  "lights": [{"type": "directional", "direction": [-0.5, -1, -0.3],
              "shadow": {"technique": "shadowmap", "filter": "hard", "bias": "slope", "cull_front": false}}]
})";

frame::FrameConfig view() {
  frame::FrameConfig c;
  c.width = 320, c.height = 240;
  return c;
}

double error_percent(const scenes::Scene& scene, const reference::FrameReference& ref, raster::Renderer& r, int size) {
  frame::FrameConfig c = view();
  c.map_size = size;
  const reference::LightScore s = reference::score_config(scene, c, r, ref).score.lights.at(0);
  EXPECT_GT(s.scored, 20000u);
  return s.percent(s.false_shadowed() + s.false_lit());
}

TEST(Convergence, ClassicMapApproachesTheReference) {
  const scenes::Scene scene = testsupport::scene_from_json(kBoxOnFloor);
  raster::Renderer r(testsupport::test_threads());
  const reference::FrameReference ref = reference::reference_for(scene, view(), r);
  const double e256 = error_percent(scene, ref, r, 256), e1024 = error_percent(scene, ref, r, 1024),
               e8192 = error_percent(scene, ref, r, 8192);
  EXPECT_LT(e8192, 0.5);
  EXPECT_GT(e256, e1024);
  EXPECT_GT(e1024, e8192);
  RecordProperty("error_256", std::to_string(e256));
  RecordProperty("error_1024", std::to_string(e1024));
  RecordProperty("error_8192", std::to_string(e8192));
  std::printf("false-shadowed + false-lit: 256: %.3f %%, 1024: %.3f %%, 8192: %.3f %%\n", e256, e1024, e8192);
}

TEST(SurfaceRecord, FloorPixelsHoldTheFloor) {
  const scenes::Scene scene = testsupport::scene_from_json(kBoxOnFloor);
  raster::Renderer r(testsupport::test_threads());
  frame::FrameConfig c = view();
  c.surface_record = true;
  const frame::Frame f = frame::render_frame(scene, c, r);
  const frame::SurfaceRecord& s = *f.surface;
  size_t floor = 0, box_top = 0;
  for (size_t p = 0; p < s.pixels(); ++p) {
    if (!s.covered[p]) continue;
    EXPECT_GT(s.depth[p], 0.0f);
    EXPECT_LT(s.depth[p], 1.0f);
    EXPECT_NEAR(glm::length(s.normal[p]), 1.0f, 1e-4f);
    const bool off_box = std::fabs(s.position[p].x) > 0.501f || std::fabs(s.position[p].z) > 0.501f;
    if (std::fabs(s.position[p].y) < 1e-4f && off_box) {
      ++floor;
      EXPECT_NEAR(s.normal[p].y, 1.0f, 1e-3f) << p;
      EXPECT_LE(std::fabs(s.position[p].x), 3.0001f);
    } else if (std::fabs(s.position[p].y - 1.0f) < 1e-4f) {
      ++box_top;
      EXPECT_NEAR(s.normal[p].y, 1.0f, 1e-3f) << p;
    }
    // Technique shadowmap: the factor is 0 or 1 (hard), and 1 wherever the technique was not asked.
    EXPECT_TRUE(s.visibility[p] == 0.0f || s.visibility[p] == 1.0f);
    if (!s.lit_facing[p]) {
      EXPECT_EQ(s.visibility[p], 1.0f);
    }
  }
  EXPECT_GT(floor, 20000u);
  EXPECT_GT(box_top, 500u);
  EXPECT_EQ(std::count(s.covered.begin(), s.covered.end(), 0) > 0, true);  // the sky
}

TEST(SurfaceRecord, SameOnBothFragmentPathsAndAnyThreadCount) {
  const scenes::Scene scene = testsupport::scene_from_json(kBoxOnFloor);
  std::optional<frame::SurfaceRecord> first;
  for (int threads : {0, 1, 2})
    for (bool quad : {false, true}) {
      raster::Renderer r(threads);
      frame::FrameConfig c = view();
      c.surface_record = true;
      c.quad_fragments = quad;
      c.filter = shading::tech::FilterKind::pcf;
      const frame::Frame f = frame::render_frame(scene, c, r);
      if (!first) {
        first = *f.surface;
        continue;
      }
      const frame::SurfaceRecord& s = *f.surface;
      EXPECT_EQ(s.covered, first->covered) << threads << (quad ? " quad" : " pair");
      EXPECT_EQ(s.visibility, first->visibility) << threads << (quad ? " quad" : " pair");
      EXPECT_EQ(s.lit_facing, first->lit_facing) << threads << (quad ? " quad" : " pair");
      EXPECT_EQ(s.depth, first->depth) << threads << (quad ? " quad" : " pair");
      EXPECT_TRUE(s.position == first->position) << threads << (quad ? " quad" : " pair");
      EXPECT_TRUE(s.normal == first->normal) << threads << (quad ? " quad" : " pair");
    }
}

}  // namespace
