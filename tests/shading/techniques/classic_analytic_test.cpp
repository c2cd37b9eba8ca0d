// Analytic cases of the classic technique where the answer is known: a square occluder's shadow covers exactly
// its area in texels (hard filter); hardware PCF across a straight shadow edge is a monotonic ramp one texel
// wide; on a tilted plane, no bias gives acne on a large share of lit points and slope bias on none.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/trigonometric.hpp>

#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// Light straight down; an 8 × 8 m box around the origin on a 256² map: 1/32 m per texel.
constexpr int kMap = 256;
constexpr float kTexel = 8.0f / kMap;

ClassicFit fixed_fit() {
  ClassicFit f;
  f.fixed = fixed_directional({0, -1, 0}, {0, 0, 0}, {4, 4}, -8.0f, 8.0f);
  return f;
}

ClassicSettings settings(FilterKind filter, BiasMode bias) {
  ClassicSettings s;
  s.filter = filter;
  s.bias.mode = bias;
  s.map_size = kMap;
  return s;
}

// A floor 8 × 8 m at y = 0 and a 2 × 2 m square at y = 1 whose edges fall on texel boundaries.
techtest::Soup floor_and_square() {
  techtest::Soup s;
  s.horizontal(-4, 4, -4, 4, 0);
  s.horizontal(-1, 1, -1, 1, 1);
  return s;
}

const ClassicLight kSun{LightKind::directional, {0, 0, 0}, {0, -1, 0}};

TEST(ClassicAnalytic, SquareOccluderShadowAreaInTexels) {
  raster::Renderer r(testsupport::test_threads());
  const auto b = techtest::build_classic(r, floor_and_square(), kSun, settings(FilterKind::hard, BiasMode::constant),
                                         fixed_fit());
  int shadowed = 0;
  for (int j = 0; j < kMap; ++j)
    for (int i = 0; i < kMap; ++i) {
      // Floor points at texel centres (view x = world x, view y = −world z for a light looking straight down).
      const glm::vec3 p(-4.0f + (float(i) + 0.5f) * kTexel, 0.0f, 4.0f - (float(j) + 0.5f) * kTexel);
      if (classic_visibility<HardFilter, false>(b.reader, p, {0, 1, 0}, {float(i), float(j)}) < 0.5f) ++shadowed;
    }
  const int side = int(2.0f / kTexel);
  EXPECT_EQ(shadowed, side * side);
}

TEST(ClassicAnalytic, PcfAcrossStraightEdgeIsOneTexelRamp) {
  raster::Renderer r(testsupport::test_threads());
  const auto b = techtest::build_classic(r, floor_and_square(), kSun, settings(FilterKind::pcf, BiasMode::constant),
                                         fixed_fit());
  // Walk along x through the occluder's left edge (x = −1) at z = 0.3.
  const int steps = 400;
  const float x0 = -1.0f - 4.0f * kTexel, dx = 8.0f * kTexel / steps;
  float prev = 2.0f, last_one = NAN, first_zero = NAN;
  for (int k = 0; k <= steps; ++k) {
    const float x = x0 + float(k) * dx;
    const float v = classic_visibility<PcfFilter, false>(b.reader, {x, 0.0f, 0.3f}, {0, 1, 0}, {0, 0});
    EXPECT_LE(v, prev) << "not monotonic at x = " << x;
    prev = v;
    if (v == 1.0f) last_one = x;
    if (v == 0.0f && std::isnan(first_zero)) first_zero = x;
  }
  ASSERT_FALSE(std::isnan(last_one));
  ASSERT_FALSE(std::isnan(first_zero));
  // Bilinear weights between the centres of the last lit and the first shadowed texel: one texel wide,
  // centred on the edge.
  EXPECT_NEAR(first_zero - last_one, kTexel, 2.0f * dx);
  EXPECT_NEAR(0.5f * (first_zero + last_one), -1.0f, 2.0f * dx);
  EXPECT_NEAR((classic_visibility<PcfFilter, false>(b.reader, {-1.0f, 0.0f, 0.3f}, {0, 1, 0}, {0, 0})), 0.5f, 1e-3f);
}

// A plane through the origin tilted 60° about z (N·L = 0.5 under a light straight down), lit everywhere.
int acne_on_slope(BiasMode bias, int* samples) {
  raster::Renderer r(testsupport::test_threads());
  const float t = std::tan(glm::radians(60.0f));
  techtest::Soup s;
  s.quad({-3, 3 * t, 3}, {3, -3 * t, 3}, {3, -3 * t, -3}, {-3, 3 * t, -3});
  const glm::vec3 n = glm::normalize(glm::vec3(t, 1.0f, 0.0f));
  const auto b = techtest::build_classic(r, s, kSun, settings(FilterKind::hard, bias), fixed_fit());
  int acne = 0;
  *samples = 0;
  // A grid not aligned with the texels: 0.0123 m steps.
  for (float x = -2.5f; x <= 2.5f; x += 0.0123f)
    for (float z = -2.5f; z <= 2.5f; z += 0.0123f) {
      ++*samples;
      if (classic_visibility<HardFilter, false>(b.reader, {x, -x * t, z}, n, {0, 0}) < 0.5f) ++acne;
    }
  return acne;
}

TEST(ClassicAnalytic, SlopeBiasRemovesAcneOnSlope) {
  int samples = 0;
  const int none = acne_on_slope(BiasMode::none, &samples);
  const int slope = acne_on_slope(BiasMode::slope, &samples);
  std::printf("slope plane: %d of %d points in false shadow without bias, %d with slope bias\n", none, samples, slope);
  EXPECT_GT(none, samples / 5);
  EXPECT_EQ(slope, 0);
}

}  // namespace
