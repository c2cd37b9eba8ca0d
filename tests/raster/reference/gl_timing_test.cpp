// llvmpipe's times on the reference workloads, printed for comparison with shadowlab's benchmarks.
// Disabled by default (they take seconds); run with
//   shadowlab_tests --gtest_also_run_disabled_tests --gtest_filter='GlTiming.*'
// Thread count: SHADOWLAB_TEST_THREADS, else 2 (the LP_NUM_THREADS=2).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/raster/reference/gl_test_support.h"

namespace {

using glref::Context;

struct Soup {
  std::vector<glm::vec4> positions;
  std::vector<uint32_t> indices;
  double mean_area_px = 0.0;
};

// `count` independent triangles of about `area_px` pixels in a size×size target: a random centre anywhere in
// the target (some triangles straddle its border), three vertices at radius r·[0.8, 1.2] and angles 120° apart
// jittered by ±20°, with r chosen so that the equilateral triangle would have the area asked. Random winding,
// per-vertex clip z uniform in [−0.9, 0.9] around a per-triangle depth, w = 1. Indexed with 0, 1, 2, ....
Soup make_soup(int count, double area_px, int size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = std::sqrt(area_px * 4.0 / (3.0 * std::sqrt(3.0)));
  const double to_ndc = 2.0 / size, pi = std::numbers::pi;
  Soup soup;
  soup.positions.reserve(size_t(count) * 3);
  double area_sum = 0.0;
  for (int t = 0; t < count; ++t) {
    const double cx = unit(rng) * size, cy = unit(rng) * size, zc = unit(rng) * 1.6 - 0.8;
    const double a0 = unit(rng) * 2.0 * pi, dir = unit(rng) < 0.5 ? 1.0 : -1.0;
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      const double angle = a0 + dir * (k * 2.0 * pi / 3.0 + (unit(rng) - 0.5) * (2.0 * pi / 9.0));
      const double radius = r * (0.8 + 0.4 * unit(rng));
      x[k] = cx + radius * std::cos(angle);
      y[k] = cy + radius * std::sin(angle);
      const double z = std::clamp(zc + (unit(rng) - 0.5) * 0.2, -0.9, 0.9);
      soup.positions.push_back({float(x[k] * to_ndc - 1.0), float(y[k] * to_ndc - 1.0), float(z), 1.0f});
    }
    area_sum += std::abs((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])) * 0.5;
  }
  soup.indices.resize(soup.positions.size());
  for (size_t i = 0; i < soup.indices.size(); ++i) soup.indices[i] = uint32_t(i);
  soup.mean_area_px = area_sum / count;
  return soup;
}

void time_soup(int count, double area_px, int repeat) {
  const int threads = testsupport::glref_threads();
  GLREF_CONTEXT_OR_SKIP(gl, threads);
  const int size = 2048;
  const Soup soup = make_soup(count, area_px, size, 1234u);
  Context::DepthDraw d;
  d.width = d.height = size;
  d.format = raster::DepthFormat::d32f;
  d.clip_positions = soup.positions;
  d.indices = soup.indices;
  std::vector<double> ms = gl->time_depth(d, repeat);
  std::vector<double> clear = gl->time_depth_clear(d, repeat);
  std::sort(ms.begin(), ms.end());
  std::sort(clear.begin(), clear.end());
  std::printf("llvmpipe %s, LP_NUM_THREADS=%d: %d triangles of mean %.1f px, d32f %dx%d, indexed: "
              "clear+draw+finish min %.1f / median %.1f / max %.1f ms (clear alone median %.2f ms)\n",
              gl->renderer().c_str(), threads, count, soup.mean_area_px, size, size, ms.front(), ms[ms.size() / 2],
              ms.back(), clear[clear.size() / 2]);
  EXPECT_GT(ms.front(), 0.0);
}

TEST(GlTiming, DISABLED_MillionSmallTriangles) { time_soup(1000000, 10.0, 7); }

TEST(GlTiming, DISABLED_TwentyThousandLargeTriangles) { time_soup(20000, 2000.0, 15); }

// Full-screen 1920×1080 shading passes reading a 2048² d32f map holding a smooth depth ramp (so the compare
// goes both ways across the screen): one hardware-PCF lookup per pixel, then 16 Poisson taps.
TEST(GlTiming, DISABLED_PcfPasses) {
  const int threads = testsupport::glref_threads();
  GLREF_CONTEXT_OR_SKIP(gl, threads);
  const int size = 2048;
  std::vector<uint32_t> texels(size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      texels[size_t(y) * size + size_t(x)] = std::bit_cast<uint32_t>(float(x + 2 * y) / float(3 * size));
  Context::ShadowSampleQuery map;
  map.tex_width = map.tex_height = size;
  map.texels = texels;
  for (int taps : {1, 16}) {
    std::vector<double> ms = gl->time_pcf_pass(1920, 1080, map, taps, 9);
    std::sort(ms.begin(), ms.end());
    std::printf("llvmpipe, LP_NUM_THREADS=%d: 1920x1080 pass, %2d PCF tap(s) on a 2048^2 d32f map: "
                "min %.1f / median %.1f / max %.1f ms\n", threads, taps, ms.front(), ms[ms.size() / 2], ms.back());
    EXPECT_GT(ms.front(), 0.0);
  }
}

}  // namespace
