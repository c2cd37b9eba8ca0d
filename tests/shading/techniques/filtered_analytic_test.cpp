// Analytic cases of the filterable maps (ESM, VSM, EVSM) where the answer is known in closed form: a single
// occluder plane over receivers at known depths (ESM exp(c (z_occ − z_r)); VSM and EVSM Chebyshev with the
// minimum variance, since a plane has none), and the light bleeding of two overlapping occluders: VSM lights
// part of the region the lower occluder shadows entirely, by the amount Chebyshev predicts for the mixed
// moments, and the light-bleeding reduction removes it.
#include <gtest/gtest.h>

#include <cmath>

#include "shading/techniques/filtered.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// Light straight down; an 8 × 8 m box around the origin, from y = 8 (depth 0) to y = −8 (depth 1), on a 256²
// map: window depth z = (8 − y) / 16, linear.
constexpr int kMap = 256;
float depth_at(float y) { return (8.0f - y) / 16.0f; }

ClassicFit fixed_fit() {
  ClassicFit f;
  f.fixed = fixed_directional({0, -1, 0}, {0, 0, 0}, {4, 4}, -8.0f, 8.0f);
  return f;
}

const ClassicLight kSun{LightKind::directional, {0, 0, 0}, {0, -1, 0}};

techtest::FilteredBuilt build(raster::Renderer& r, const techtest::Soup& soup, const MomentParams& m, int radius) {
  return techtest::build_filtered(r, soup, kSun, fixed_fit(), kMap, m, radius);
}

// One occluder plane at y = 1 over the whole map.
techtest::Soup occluder_plane() {
  techtest::Soup s;
  s.horizontal(-6, 6, -6, 6, 1.0f);
  return s;
}

constexpr float kHeights[] = {0.999f, 0.99f, 0.95f, 0.9f, 0.8f, 0.5f, 0.0f};

TEST(FilteredAnalytic, EsmSingleOccluderPlaneIsExponential) {
  raster::Renderer r(testsupport::test_threads());
  for (float c : {20.0f, 80.0f}) {
    MomentParams m;
    m.kind = MomentKind::esm;
    m.esm_c = c;
    const techtest::FilteredBuilt f = build(r, occluder_plane(), m, 2);
    for (float y : kHeights) {
      const float expected = std::exp(c * (depth_at(1.0f) - depth_at(y)));
      const float got = filtered_visibility(f.map.reader, {0.37f, y, -1.21f}, {0, 1, 0});
      EXPECT_NEAR(got, expected, 1e-4f + 1e-3f * expected) << "c = " << c << ", receiver at y = " << y;
    }
    // Above the occluder: lit.
    EXPECT_EQ(filtered_visibility(f.map.reader, {0.37f, 1.5f, -1.21f}, {0, 1, 0}), 1.0f);
  }
}

TEST(FilteredAnalytic, VsmSingleOccluderPlaneIsChebyshevOfMinimumVariance) {
  raster::Renderer r(testsupport::test_threads());
  MomentParams m;
  m.kind = MomentKind::vsm;
  m.light_bleed = 0.0f;
  m.min_variance = 1e-4f;
  const techtest::FilteredBuilt f = build(r, occluder_plane(), m, 2);
  for (float y : kHeights) {
    const float d = depth_at(y) - depth_at(1.0f);
    const float expected = m.min_variance / (m.min_variance + d * d);
    EXPECT_NEAR(filtered_visibility(f.map.reader, {-1.3f, y, 2.2f}, {0, 1, 0}), expected, 2e-3f) << "y = " << y;
  }
  EXPECT_EQ(filtered_visibility(f.map.reader, {-1.3f, 1.5f, 2.2f}, {0, 1, 0}), 1.0f);
}

TEST(FilteredAnalytic, EvsmSingleOccluderPlaneFollowsTheWarpedBound) {
  raster::Renderer r(testsupport::test_threads());
  for (MomentKind kind : {MomentKind::evsm2, MomentKind::evsm4}) {
    MomentParams m;
    m.kind = kind;
    m.light_bleed = 0.0f;
    m.min_variance = 1e-7f;
    const techtest::FilteredBuilt f = build(r, occluder_plane(), m, 2);
    for (float y : kHeights) {
      const float zo = depth_at(1.0f), zr = depth_at(y);
      const glm::vec4 mo = moments(m, zo);  // a plane: the blurred texel is the plane's own moments
      const float expected = moment_visibility(m, mo, zr);
      const float ep = evsm_positive(zr, m.positive), eo = evsm_positive(zo, m.positive);
      const float dp = 2.0f * m.positive * ep, vp = m.min_variance * dp * dp;
      float bound = vp / (vp + (ep - eo) * (ep - eo));  // the positive warp's bound, written out
      if (kind == MomentKind::evsm4) {
        const float en = evsm_negative(zr, m.negative), no = evsm_negative(zo, m.negative);
        const float dn = 2.0f * m.negative * en, vn = m.min_variance * dn * dn;
        bound = std::min(bound, vn / (vn + (en - no) * (en - no)));
      }
      EXPECT_NEAR(expected, bound, 1e-4f) << "y = " << y;
      EXPECT_NEAR(filtered_visibility(f.map.reader, {0.5f, y, 0.5f}, {0, 1, 0}), bound, 2e-3f + 0.02f * bound)
          << "y = " << y;
    }
    // Darker the deeper the receiver: at 0.5 m under the plane almost nothing is left.
    float prev = 2.0f;
    for (float y : kHeights) {
      const float v = filtered_visibility(f.map.reader, {0.5f, y, 0.5f}, {0, 1, 0});
      EXPECT_LT(v, prev) << "y = " << y;
      prev = v;
    }
    EXPECT_LT(filtered_visibility(f.map.reader, {0.5f, 0.5f, 0.5f}, {0, 1, 0}), 0.01f);
  }
}

// Two overlapping occluders: A at y = 3 over x < 0, B at y = 1 over everything. The floor at y = 0 is entirely
// in B's shadow; near A's edge the blurred moments mix A's and B's depths, and VSM lights the floor there.
struct Bleeding {
  float at_edge = 0.0f;   // visibility on the floor under A's edge
  int bleeding = 0;       // floor points (all truly shadowed) with visibility above 0.05
  int samples = 0;
};

Bleeding bleeding(MomentKind kind, float amount) {
  raster::Renderer r(testsupport::test_threads());
  techtest::Soup s;
  s.horizontal(-6, 0, -6, 6, 3.0f);
  s.horizontal(-6, 6, -6, 6, 1.0f);
  MomentParams m;
  m.kind = kind;
  m.light_bleed = amount;
  if (kind != MomentKind::vsm) m.min_variance = 1e-7f;  // the evsm_min_variance default
  const techtest::FilteredBuilt f = build(r, s, m, 8);
  Bleeding b;
  b.at_edge = filtered_visibility(f.map.reader, {0.0f, 0.0f, 0.3f}, {0, 1, 0});
  for (float x = -1.0f; x <= 1.0f; x += 0.01f) {
    ++b.samples;
    if (filtered_visibility(f.map.reader, {x, 0.0f, 0.3f}, {0, 1, 0}) > 0.05f) ++b.bleeding;
  }
  return b;
}

TEST(FilteredAnalytic, VsmBleedsLightBetweenOverlappingOccludersAndTheReductionRemovesIt) {
  // Under A's edge the 17-texel box holds half A, half B (the edge lies on a texel boundary of the map):
  // mean μ = (zA + zB) / 2, variance ((zB − zA) / 2)², and the floor gets Chebyshev's bound.
  const float za = depth_at(3.0f), zb = depth_at(1.0f), zr = depth_at(0.0f);
  const float mu = 0.5f * (za + zb), var = 0.25f * (zb - za) * (zb - za);
  const float predicted = var / (var + (zr - mu) * (zr - mu));
  const Bleeding plain = bleeding(MomentKind::vsm, 0.0f);
  std::printf("VSM light bleeding: %.3f at the edge (Chebyshev predicts %.3f), %d of %d floor points above 0.05\n",
              plain.at_edge, predicted, plain.bleeding, plain.samples);
  EXPECT_NEAR(plain.at_edge, predicted, 0.01f);
  EXPECT_GT(plain.bleeding, plain.samples / 20);
  // linstep(amount, 1, p): any amount above the largest bound removes it.
  const Bleeding reduced = bleeding(MomentKind::vsm, predicted + 0.05f);
  std::printf("with light_bleed %.2f: %.3f at the edge, %d points above 0.05\n", predicted + 0.05f, reduced.at_edge,
              reduced.bleeding);
  EXPECT_EQ(reduced.at_edge, 0.0f);
  EXPECT_EQ(reduced.bleeding, 0);
  // A smaller amount shrinks the bleeding area without removing it.
  const Bleeding partly = bleeding(MomentKind::vsm, 0.5f * predicted);
  EXPECT_LT(partly.bleeding, plain.bleeding);
  EXPECT_GT(partly.bleeding, 0);
  // EVSM's exponential warp makes the receiver far from the mixed moments: no bleeding without the setting.
  const Bleeding evsm = bleeding(MomentKind::evsm4, 0.0f);
  std::printf("EVSM4: %.4f at the edge, %d points above 0.05\n", evsm.at_edge, evsm.bleeding);
  EXPECT_LT(evsm.bleeding, plain.bleeding / 4);
}

TEST(FilteredAnalytic, BlurKeepsAStraightEdgeMonotonicAndCentred) {
  raster::Renderer r(testsupport::test_threads());
  techtest::Soup s;
  s.horizontal(-6, 0, -6, 6, 1.0f);
  MomentParams m;
  m.kind = MomentKind::esm;
  const techtest::FilteredBuilt f = build(r, s, m, 4);
  float prev = -1.0f;
  for (float x = -0.5f; x <= 0.5f; x += 0.005f) {
    const float v = filtered_visibility(f.map.reader, {x, 0.0f, 0.1f}, {0, 1, 0});
    EXPECT_GE(v, prev) << "x = " << x;
    prev = v;
  }
  // 9 texels of box blur: 9 / 32 m wide; beyond it, ESM's closed form of the plane 1 m above, and fully lit.
  EXPECT_NEAR(filtered_visibility(f.map.reader, {-0.3f, 0.0f, 0.1f}, {0, 1, 0}),
              std::exp(m.esm_c * (depth_at(1.0f) - depth_at(0.0f))), 1e-5f);
  EXPECT_GT(filtered_visibility(f.map.reader, {0.3f, 0.0f, 0.1f}, {0, 1, 0}), 0.999f);
}

}  // namespace
