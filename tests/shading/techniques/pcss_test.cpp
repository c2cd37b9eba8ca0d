// PCSS on constructed scenes: the penumbra under a straight occluder edge grows linearly with the distance
// between receiver and occluder, as similar triangles say for a light of a given angular size, within 10 %;
// no blocker in the search region means fully lit (the early exit); a spot light's penumbra follows its radius.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shading/techniques/pcss.h"
#include "shading/techniques/poisson.h"
#include "tests/shading/techniques/pcss_test_util.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// Light straight down over an 8 × 8 m box, 16 m deep, on a 1024² map: 1/128 m per texel.
constexpr int kMap = 1024;
constexpr float kTexel = 8.0f / kMap;
constexpr float kAngle = 5.0f;  // degrees

const ClassicLight kSun{LightKind::directional, {0, 0, 0}, {0, -1, 0}};

struct Built {
  std::unique_ptr<ShadowMapSet> set;
  PcssReader reader;
};

Built build(raster::Renderer& r, const techtest::Soup& soup, const ClassicLight& light, const ClassicFit& fit,
            float size) {
  ClassicSettings s;
  s.bias.mode = BiasMode::constant;
  s.bias.constant = 0.0005f;
  s.map_size = kMap;
  s.depth_format = raster::DepthFormat::d32f;
  Built b;
  b.set = std::make_unique<ShadowMapSet>(plan_classic_map(light, s, fit));
  build_maps(r, *b.set, shading::tech::CasterGeometry{soup.positions, soup.indices, {}}, classic_depth_options(s));
  b.reader = make_pcss_reader(*b.set, light, s, size);
  return b;
}

ClassicFit fixed_fit() {
  ClassicFit f;
  f.fixed = fixed_directional({0, -1, 0}, {0, 0, 0}, {4, 4}, -8.0f, 8.0f);
  return f;
}

// The mean visibility profile across a straight edge along z at x = 0: visibility at x, averaged over many
// pixels (each its own turn of the disc), and the distance between its 10 % and 90 % crossings.
float penumbra_width(const Built& b, float y, float step) {
  const int rows = 256;
  return techtest::measured_width(1.0f, step, rows, [&](float x, int j, glm::vec2 frag) {
    return pcss_visibility(b.reader, {x, y, -1.0f + 2.0f * float(j) / rows}, {0, 1, 0}, frag);
  });
}

TEST(Pcss, PenumbraGrowsLinearlyWithReceiverBlockerDistance) {
  raster::Renderer r(testsupport::test_threads());
  const float tan_half = std::tan(0.5f * kAngle * 3.14159265f / 180.0f);
  std::vector<float> ratio;
  for (float h : {1.0f, 2.0f, 3.0f, 4.0f}) {
    // An occluder over x < 0 at height h above the floor (y = 0); the receiver points are on the floor.
    techtest::Soup s;
    s.horizontal(-6, 0, -6, 6, h);
    s.horizontal(-6, 6, -6, 6, 0.0f);
    const Built b = build(r, s, kSun, fixed_fit(), kAngle);
    const float measured = penumbra_width(b, 0.0f, kTexel / 4.0f);
    const float k = h * tan_half;  // the kernel radius similar triangles give, metres
    const float ideal = techtest::ideal_pcss_width(k);
    std::printf("h = %.1f m: penumbra (10-90 %%) %.4f m = %.1f texels, ideal %.4f m (kernel %.4f m)\n", h, measured,
                measured / kTexel, ideal, k);
    EXPECT_NEAR(measured, ideal, 0.1f * ideal) << "h = " << h;
    ratio.push_back(measured / h);
  }
  // Linear: width / distance is the same at every distance, within 10 %.
  const auto [lo, hi] = std::minmax_element(ratio.begin(), ratio.end());
  EXPECT_LT(*hi / *lo, 1.1f);
}

TEST(Pcss, NoBlockerInTheSearchRegionIsLitAtOnce) {
  raster::Renderer r(testsupport::test_threads());
  techtest::Soup s;
  s.horizontal(-6, 0, -6, 6, 1.0f);
  s.horizontal(-6, 6, -6, 6, 0.0f);
  const Built b = build(r, s, kSun, fixed_fit(), kAngle);
  // The search radius at the floor: its depth (8 m below the map's near plane) times tan(θ/2).
  const glm::vec2 search = pcss_search_radius(b.reader, 0.5f);
  EXPECT_NEAR(search.x * 8.0f, 8.0f * std::tan(0.5f * kAngle * 3.14159265f / 180.0f), 1e-4f);
  // Beyond the search region from the edge: exactly 1; deep under the occluder: exactly 0.
  const float clear = search.x * 8.0f * 1.3f + kTexel;  // the disc reaches 1.23 radii
  EXPECT_EQ(pcss_visibility(b.reader, {clear, 0.0f, 0.2f}, {0, 1, 0}, {3, 4}), 1.0f);
  EXPECT_EQ(pcss_visibility(b.reader, {-clear, 0.0f, 0.2f}, {0, 1, 0}, {3, 4}), 0.0f);
  // 0.1 m from the edge: outside the 5° light's kernel (1 m · tan 2.5° · 1.23 = 0.054 m), fully lit; inside
  // the 20° light's (0.22 m), partly shadowed.
  EXPECT_EQ(pcss_visibility(b.reader, {0.1f, 0.0f, 0.2f}, {0, 1, 0}, {3, 4}), 1.0f);
  const Built wide = build(r, s, kSun, fixed_fit(), 4.0f * kAngle);
  const float v = pcss_visibility(wide.reader, {0.1f, 0.0f, 0.2f}, {0, 1, 0}, {3, 4});
  EXPECT_LT(v, 1.0f);
  EXPECT_GT(v, 0.5f);
}

TEST(Pcss, SpotPenumbraFollowsTheLightRadius) {
  raster::Renderer r(testsupport::test_threads());
  // A spot 8 m above the floor looking down, an occluder edge at x = 0, 2 m above the floor.
  const ClassicLight spot{LightKind::spot, {0, 8, 0}, {0, -1, 0}, 0.5f, 20.0f};
  techtest::Soup s;
  s.horizontal(-6, 0, -6, 6, 2.0f);
  s.horizontal(-8, 8, -8, 8, 0.0f);
  std::vector<float> widths;
  for (float radius : {0.1f, 0.2f, 0.4f}) {
    const Built b = build(r, s, spot, ClassicFit{}, radius);
    // Similar triangles: penumbra on the floor = 2 R · (8 − 6) / 6 … the shadow edge is at x = 0 · 8/6 = 0.
    const float k = radius * 2.0f / 6.0f;
    const float measured = penumbra_width(b, 0.0f, 0.002f);
    std::printf("spot radius %.2f m: penumbra %.4f m, ideal %.4f m\n", radius, measured, techtest::ideal_pcss_width(k));
    EXPECT_NEAR(measured, techtest::ideal_pcss_width(k), 0.15f * techtest::ideal_pcss_width(k)) << "radius " << radius;
    widths.push_back(measured);
  }
  EXPECT_NEAR(widths[2] / widths[0], 4.0f, 0.4f);
}

}  // namespace
