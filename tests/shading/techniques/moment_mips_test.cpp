// The mip chains of the blurred moment maps (`moment_mips`): every level's texel is the box mean of its four
// parents, exactly, for the classic map, each cube face and each cascade's slice; and a receiver whose pixel
// covers many texels reads a coarser level. The test scene is a floor under bars 2 texels wide every 4 texels:
// minified, a pixel's ideal visibility is the bars' coverage, 1/2 (a heavily supersampled reference, the mean of
// level-0 lookups over the pixel's footprint, agrees), and VSM gives exactly 1 − coverage for the mean moments
// of two depths, so the trilinear lookup is right within rounding while level 0 alone aliases between 0 and 1.
// Near (magnified) receivers read level 0 bit for bit as without mips; the answer is the same at any thread
// count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shading/mip_chain.h"
#include "shading/techniques/cascades.h"
#include "shading/techniques/cube_map.h"
#include "shading/techniques/filtered.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;
using shading::MipFilter;

namespace {

// The camera over the floor (technique_test_util.h).
CameraView camera() { return techtest::floor_camera(); }

// Light straight down over an 8 × 8 m box, y from 8 (depth 0) to −8 (depth 1), on a 256² map: 3.125 cm texels.
constexpr int kMap = 256;
constexpr float kTexel = 8.0f / kMap;
const ClassicLight kSun{LightKind::directional, {0, 0, 0}, {0, -1, 0}};

ClassicFit fixed_fit() {
  ClassicFit f;
  f.fixed = fixed_directional({0, -1, 0}, {0, 0, 0}, {4, 4}, -8.0f, 8.0f);
  return f;
}

// A floor at y = 0 (in the map too, so that lit texels hold its depth) and, at y = 1, bars along z covering map
// columns [4k, 4k + 2) over x in [−4, 4]: half of every 4-texel period.
techtest::Soup floor_and_bars(float period = 4 * kTexel, float z0 = -4.0f, float z1 = 4.0f) {
  techtest::Soup s;
  s.horizontal(-30, 30, -60, 30, 0.0f);
  for (float x = -4.0f; x < 4.0f; x += period) s.horizontal(x, x + period / 2, z0, z1, 1.0f);
  return s;
}

MomentParams vsm(MipFilter mips) {
  MomentParams m;
  m.kind = MomentKind::vsm;
  m.light_bleed = 0.0f;
  m.min_variance = 1e-6f;
  m.mips = mips;
  return m;
}

techtest::FilteredBuilt build(raster::Renderer& r, const techtest::Soup& soup, const MomentParams& m, int radius) {
  return techtest::build_filtered(r, soup, kSun, fixed_fit(), kMap, m, radius);
}

// Every texel of every level l >= 1 equals the mean of its four parents, computed in double and rounded once
// (the sum of four floats divided by 4), channel by channel. Returns the number of texels compared.
size_t expect_box_means(const shading::Texture2D& t, const std::string& what) {
  size_t compared = 0;
  for (int l = 1; l < t.levels(); ++l) {
    for (int j = 0; j < t.height(l); ++j)
      for (int i = 0; i < t.width(l); ++i) {
        const glm::vec4 a = t.texel(2 * i, 2 * j, l - 1), b = t.texel(2 * i + 1, 2 * j, l - 1);
        const glm::vec4 c = t.texel(2 * i, 2 * j + 1, l - 1), d = t.texel(2 * i + 1, 2 * j + 1, l - 1);
        const glm::vec4 got = t.texel(i, j, l);
        for (int k = 0; k < 4; ++k) {
          const float want = float((double(a[k]) + double(b[k]) + double(c[k]) + double(d[k])) / 4.0);
          if (got[k] != want) {
            ADD_FAILURE() << what << ": level " << l << " texel (" << i << ", " << j << ") channel " << k << " is "
                          << got[k] << ", the mean of its parents is " << want;
            return compared;
          }
        }
        ++compared;
      }
  }
  return compared;
}

float read(const FilteredReader& r, glm::vec3 p, glm::vec3 dpdx, glm::vec3 dpdy) {
  ShadowQuery q{p, {0, 1, 0}, glm::vec2(0.0f)};
  q.dpdx = dpdx, q.dpdy = dpdy;
  return filtered_visibility(r, q);
}

TEST(MomentMips, EachLevelIsTheBoxMeanOfItsParents) {
  raster::Renderer r(testsupport::test_threads());
  const techtest::Soup soup = floor_and_bars(3.3f * kTexel);  // a period that is not a power of two
  for (MomentKind kind : {MomentKind::esm, MomentKind::vsm, MomentKind::evsm2, MomentKind::evsm4}) {
    MomentParams m = vsm(MipFilter::linear);
    m.kind = kind;
    m.esm_c = 40.0f;
    const techtest::FilteredBuilt f = build(r, soup, m, 1);
    const shading::Texture2D& t = f.map.reader.moments;
    ASSERT_EQ(t.levels(), shading::mip_level_count(kMap, kMap));
    EXPECT_FALSE(t.owns_level(0)) << "level 0 is the blurred target itself";
    size_t texels = 0;
    for (int l = 1; l < t.levels(); ++l) texels += size_t(t.width(l)) * size_t(t.height(l));
    EXPECT_EQ(expect_box_means(t, "kind " + std::to_string(int(kind))), texels);
    EXPECT_EQ(f.map.reader.sampler.mip_filter, shading::MipFilter::linear);
  }
  // moment_mips = none: level 0 alone.
  EXPECT_EQ(build(r, soup, vsm(MipFilter::none), 1).map.reader.moments.levels(), 1);
}

TEST(MomentMips, EachCubeFaceHasItsOwnChain) {
  raster::Renderer r(testsupport::test_threads());
  OmniLight light;
  light.range = 10.0f;
  OmniSettings s;
  s.map_size = 64;
  s.depth_format = raster::DepthFormat::d32f;
  ShadowMapSet set = plan_cube_map(light, s);
  techtest::Soup soup;
  soup.horizontal(-30, 30, -30, 30, -3.0f);
  for (float x = -3.0f; x < 3.0f; x += 0.37f) soup.horizontal(x, x + 0.2f, -3, 3, -1.0f);
  build_cube_map(r, set, light, s, CasterGeometry{soup.positions, soup.indices, {}});
  CubeMoments m;
  m.params = vsm(MipFilter::linear);
  m.blur_radius = 1;
  build_cube_moments(r, set, true, m);
  ASSERT_EQ(m.cube.levels(), shading::mip_level_count(64, 64));
  EXPECT_EQ(m.sampler.mip_filter, shading::MipFilter::linear);
  for (int f = 0; f < 6; ++f) EXPECT_GT(expect_box_means(m.cube.face(f), "face " + std::to_string(f)), 0u);
}

// Points on the floor across the bars' region, each the centre of a pixel whose footprint is `footprint` metres
// wide along x and along z; their visibility, and the supersampled reference: the mean of 32 × 32 level-0 lookups
// spread over the footprint.
struct Row {
  std::vector<float> vis, reference;
};

Row floor_row(const FilteredReader& r, float footprint) {
  Row row;
  const glm::vec3 dx(footprint, 0, 0), dz(0, 0, footprint);
  for (int k = 0; k < 61; ++k) {
    const glm::vec3 p(-3.0f + 0.0997f * float(k), 0.0f, 0.37f);
    row.vis.push_back(read(r, p, dx, dz));
    double sum = 0.0;
    for (int a = 0; a < 32; ++a)
      for (int b = 0; b < 32; ++b)
        sum += filtered_visibility(r, p + dx * ((float(a) + 0.5f) / 32.0f - 0.5f) + dz * ((float(b) + 0.5f) / 32.0f - 0.5f),
                                   {0, 1, 0});
    row.reference.push_back(float(sum / 1024.0));
  }
  return row;
}

float rms_error(const Row& row) {
  double e = 0.0;
  for (size_t i = 0; i < row.vis.size(); ++i) e += double(row.vis[i] - row.reference[i]) * (row.vis[i] - row.reference[i]);
  return float(std::sqrt(e / double(row.vis.size())));
}

float spread(std::span<const float> v) {
  double m = 0.0, m2 = 0.0;
  for (float x : v) m += x, m2 += double(x) * x;
  m /= double(v.size());
  return float(std::sqrt(std::max(0.0, m2 / double(v.size()) - m * m)));
}

TEST(MomentMips, AMinifiedReceiverReadsACoarserLevelAndDoesNotAlias) {
  raster::Renderer r(testsupport::test_threads());
  const techtest::Soup soup = floor_and_bars();
  const techtest::FilteredBuilt none = build(r, soup, vsm(MipFilter::none), 0);
  const techtest::FilteredBuilt trilinear = build(r, soup, vsm(MipFilter::linear), 0);
  const techtest::FilteredBuilt nearest = build(r, soup, vsm(MipFilter::nearest), 0);
  // A pixel 24 texels wide (λ = 4.58, between levels 4 and 5): six whole periods, so the reference is the bars'
  // coverage, 1/2, wherever the pixel lies.
  const float footprint = 24.0f * kTexel;
  const Row a = floor_row(none.map.reader, footprint), b = floor_row(trilinear.map.reader, footprint),
            c = floor_row(nearest.map.reader, footprint);
  for (float ref : a.reference) EXPECT_NEAR(ref, 0.5f, 0.01f) << "the supersampled reference";
  // Level 0 alone: every pixel takes one point of the pattern, anywhere between 0 and 1.
  EXPECT_GT(rms_error(a), 0.25f);
  EXPECT_GT(spread(a.vis), 0.25f);
  // The mip chain: the mean moments of the footprint, whose Chebyshev bound is 1 − coverage.
  for (const Row* m : {&b, &c}) {
    EXPECT_LT(rms_error(*m), 0.01f);
    EXPECT_LT(spread(m->vis), 0.01f);
  }
  std::printf("[ moment mips ] rms error against the supersampled reference: level 0 %.4f, trilinear %.4f, nearest "
              "level %.4f; spread of visibility %.4f, %.4f, %.4f\n",
              rms_error(a), rms_error(b), rms_error(c), spread(a.vis), spread(b.vis), spread(c.vis));
}

TEST(MomentMips, AMagnifiedReceiverReadsLevelZeroAsWithoutMips) {
  raster::Renderer r(testsupport::test_threads());
  const techtest::Soup soup = floor_and_bars();
  const techtest::FilteredBuilt none = build(r, soup, vsm(MipFilter::none), 1);
  const techtest::FilteredBuilt mips = build(r, soup, vsm(MipFilter::linear), 1);
  int partial = 0;
  for (int k = 0; k < 200; ++k) {
    const glm::vec3 p(-3.0f + 0.0301f * float(k), 0.0f, 0.37f);
    // A pixel of 0.9 texels (λ < 0): magnification, level 0.
    const float v = read(mips.map.reader, p, {0.9f * kTexel, 0, 0}, {0, 0, 0.9f * kTexel});
    EXPECT_EQ(v, read(none.map.reader, p, {0.9f * kTexel, 0, 0}, {0, 0, 0.9f * kTexel})) << "at x = " << p.x;
    EXPECT_EQ(v, filtered_visibility(mips.map.reader, p, {0, 1, 0})) << "no derivatives: level 0";
    partial += v > 0.05f && v < 0.95f;
  }
  EXPECT_GT(partial, 20) << "the points must cross the bars' edges";
}

TEST(MomentMips, SameAnswerAtAnyThreadCount) {
  const techtest::Soup soup = floor_and_bars(3.3f * kTexel);
  std::vector<float> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    const techtest::FilteredBuilt f = build(r, soup, vsm(MipFilter::linear), 2);
    std::vector<float> got;
    for (int l = 0; l < f.map.reader.moments.levels(); ++l)
      for (int j = 0; j < f.map.reader.moments.height(l); ++j)
        for (int i = 0; i < f.map.reader.moments.width(l); ++i) {
          const glm::vec4 t = f.map.reader.moments.texel(i, j, l);
          got.insert(got.end(), {t.x, t.y});
        }
    for (int k = 0; k < 50; ++k)
      got.push_back(read(f.map.reader, {-3.0f + 0.121f * float(k), 0.0f, 0.2f}, {0.05f * float(k), 0, 0}, {0, 0, 0.1f}));
    if (first.empty()) first = got;
    else EXPECT_EQ(got, first) << threads << " threads";
  }
}

// Cascades: each slice's moment map has its own chain and its own texel size, so the level follows the slice.
// A camera over the floor looking down −z; bars 0.25 m apart everywhere; pixels 1 m wide along x read the bars'
// coverage (1/2) in every slice with mips, and alias without.
TEST(MomentMips, EveryCascadeReadsItsOwnLevel) {
  raster::Renderer r(testsupport::test_threads());
  techtest::Soup soup;
  soup.horizontal(-30, 30, -60, 30, 0.0f);
  for (float x = -20.0f; x < 20.0f; x += 0.25f) soup.horizontal(x, x + 0.125f, -50, 12, 0.5f);
  PlanInputs in;
  in.casters = Box{{-30.0f, 0.0f, -60.0f}, {30.0f, 0.5f, 30.0f}};
  in.scene_receivers = Box{{-20.0f, 0.0f, -48.0f}, {20.0f, 0.0f, 12.0f}};
  in.receivers = in.scene_receivers;
  in.camera = camera();
  in.eye = in.camera.eye;
  in.camera_view_proj = in.camera.proj * in.camera.view;
  const LightDesc sun{LightType::directional, {}, {0.0f, -1.0f, 0.0f}};
  CascadeSettings cs;
  cs.count = 3;
  const CascadePlan plan = plan_cascade_fits(sun, cs, 512, in);
  for (const char* mips : {"linear", "none"}) {
    ShadowConfig c;
    c.technique = Technique::cascades;
    c.map_size = 512;
    c.depth_format = DepthFormat::d32f;
    c.bias.mode = BiasMode::none;
    c.params = {{"moments", std::string("vsm")}, {"cascades", 3.0}, {"light_bleed", 0.0}, {"min_variance", 1e-7},
                {"blur_radius", 0.0}, {"moment_mips", std::string(mips)}};
    auto shadow = plan_cascades(sun, c, in);
    shadow->build(r, CasterGeometry{soup.positions, soup.indices, {}});
    std::set<size_t> slices;
    for (float d : {6.0f, 9.0f, 13.0f, 18.0f, 25.0f, 35.0f, 45.0f}) {
      std::vector<float> vis;
      for (int k = 0; k < 41; ++k) {
        ShadowQuery q{{-2.0f + 0.0973f * float(k), 0.0f, camera().eye.z - d}, {0, 1, 0}, glm::vec2(0.0f)};
        q.dpdx = {1.0f, 0.0f, 0.0f}, q.dpdy = {0.0f, 0.0f, 1.0f};
        float v = -1.0f;
        shadow->visibility(std::span(&q, 1), std::span(&v, 1));
        vis.push_back(v);
      }
      const size_t slice = choose_slice(plan.splits, 0.0f, view_distance(camera(), {0.0f, 0.0f, camera().eye.z - d})).slice;
      slices.insert(slice);
      double mean = 0.0;
      for (float v : vis) mean += v / double(vis.size());
      std::printf("[ moment mips ] cascades, mips %s, %.0f m (slice %zu): mean %.3f, spread %.3f\n", mips, d, slice, mean,
                  spread(vis));
      if (std::string(mips) == "linear") {
        EXPECT_NEAR(mean, 0.5, 0.1) << "slice " << slice << " at " << d << " m";
        EXPECT_LT(spread(vis), 0.1f) << "slice " << slice << " at " << d << " m";
      } else {
        EXPECT_GT(spread(vis), 0.3f) << "slice " << slice << " at " << d << " m: level 0 alone aliases";
      }
    }
    EXPECT_EQ(slices.size(), 3u) << "the distances must reach every slice";
  }
}

}  // namespace
