// The scoring rules on hand-made records: which pixels count, false-shadowed against false-lit, near a boundary
// of the exact image or elsewhere, mean |S - V|, and the connected groups of false-lit pixels.
#include <gtest/gtest.h>

#include "scenes/reference/shadow_score.h"

namespace {

// A w x h record, every pixel covered and lit-facing for one light, normal +Y; the exact image lit everywhere.
struct Case {
  frame::SurfaceRecord record;
  reference::ExactVisibility exact;
  Case(int w, int h) : record(w, h, 1) {
    for (size_t p = 0; p < record.pixels(); ++p) {
      record.covered[p] = 1;
      record.normal[p] = {0.0f, 1.0f, 0.0f};
      record.lit_facing[p] = 1;
    }
    exact.width = w, exact.height = h, exact.lights = 1;
    exact.reached.assign(record.pixels(), 1);
    exact.visible.assign(record.pixels(), 1);
  }
  void exact_shadow(int x, int y) { exact.visible[record.index(x, y)] = 0; }
  void technique(int x, int y, float s) { record.visibility[record.index(x, y)] = s; }
};

TEST(ShadowScore, FalseShadowedAndFalseLitNearAndElsewhere) {
  Case c(20, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) c.exact_shadow(x, y);  // the left half is in shadow: boundary at x = 9 | 10
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) c.technique(x, y, 0.0f);  // the technique agrees...
  c.technique(9, 5, 1.0f);   // ...but for a leak on the boundary (near),
  c.technique(0, 0, 0.75f);  // a lit pixel deep in the shadow (elsewhere: 9 pixels from the boundary),
  c.technique(19, 9, 0.25f); // acne far from it (elsewhere),
  c.technique(11, 2, 0.4f);  // acne 2 pixels from it (near)
  c.technique(12, 2, 0.5f);  // and 0.5, which is lit: no error
  const reference::FrameScore s = reference::score_frame(c.record, c.exact);
  ASSERT_EQ(s.lights.size(), 1u);
  const reference::LightScore& l = s.lights[0];
  EXPECT_EQ(l.scored, 200u);
  EXPECT_EQ(l.false_lit_near, 1u);
  EXPECT_EQ(l.false_lit_elsewhere, 1u);
  EXPECT_EQ(l.false_shadowed_near, 1u);
  EXPECT_EQ(l.false_shadowed_elsewhere, 1u);
  EXPECT_DOUBLE_EQ(l.percent(l.false_lit()), 1.0);
  EXPECT_NEAR(l.mean_abs_error, (1.0 + 0.75 + 0.75 + 0.6 + 0.5) / 200.0, 1e-9);
  EXPECT_EQ(s.errors[c.record.index(9, 5)], reference::kFalseLit);
  EXPECT_EQ(s.errors[c.record.index(19, 9)], reference::kFalseShadowed);
  EXPECT_EQ(s.errors[c.record.index(12, 2)], 0);
  // With a near radius of 0 only the boundary pixels themselves are near.
  const reference::LightScore tight = reference::score_frame(c.record, c.exact, {0.5f, 0}).lights[0];
  EXPECT_EQ(tight.false_lit_near, 1u);
  EXPECT_EQ(tight.false_shadowed_near, 0u);
}

TEST(ShadowScore, OnlyLitFacingCoveredPixelsCount) {
  Case c(4, 4);
  c.record.covered[c.record.index(0, 0)] = 0;
  c.record.lit_facing[c.record.index(1, 0)] = 0;
  c.technique(1, 0, 0.0f);  // not asked: ignored
  c.exact.reached[c.record.index(2, 0)] = 0;  // asked, but its triangle faces away: unreached
  c.exact.visible[c.record.index(2, 0)] = 0;
  const reference::LightScore l = reference::score_frame(c.record, c.exact).lights[0];
  EXPECT_EQ(l.scored, 13u);
  EXPECT_EQ(l.unreached, 1u);
  EXPECT_EQ(l.false_shadowed(), 0u);
  EXPECT_EQ(l.false_lit(), 0u);
}

TEST(ShadowScore, CreasesAreBoundaries) {
  Case c(10, 10);
  for (int y = 5; y < 10; ++y)
    for (int x = 0; x < 10; ++x) c.record.normal[c.record.index(x, y)] = {1.0f, 0.0f, 0.0f};  // a wall above
  const std::vector<uint8_t> b = reference::exact_boundaries(c.record, c.exact, 0);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) EXPECT_EQ(b[c.record.index(x, y)], (y == 4 || y == 5) ? 1 : 0) << x << "," << y;
}

TEST(ShadowScore, FalseLitGroups) {
  Case c(30, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 30; ++x) c.exact_shadow(x, y), c.technique(x, y, 0.0f);
  for (int x = 2; x < 14; ++x) c.technique(x, 3 + (x % 2), 1.0f);  // a 12-pixel diagonal zig-zag: one group
  c.technique(20, 8, 1.0f);
  c.technique(21, 8, 1.0f);
  const reference::LightScore l = reference::score_frame(c.record, c.exact).lights[0];
  EXPECT_EQ(l.false_lit(), 14u);
  EXPECT_EQ(l.largest_false_lit_group, 12u);
  EXPECT_EQ(l.longest_false_lit_run, 12);
}

TEST(ShadowScore, SizesMustMatch) {
  Case a(4, 4), b(5, 4);
  EXPECT_THROW(reference::score_frame(a.record, b.exact), reference::ReferenceError);
}

TEST(ShadowScore, DilateIsChebyshev) {
  std::vector<uint8_t> m(7 * 7, 0);
  m[3 * 7 + 3] = 1;
  const std::vector<uint8_t> d = reference::dilate(m, 7, 7, 2);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 7; ++x) EXPECT_EQ(d[size_t(y * 7 + x)], (std::abs(x - 3) <= 2 && std::abs(y - 3) <= 2) ? 1 : 0);
}

}  // namespace
