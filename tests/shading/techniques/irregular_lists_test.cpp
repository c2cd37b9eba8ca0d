// The irregular z-buffer's two-level sample lists (shading/techniques/irregular_lists.h): every sample in exactly
// one list, in sample order, inside its cell; a crowded top cell split by a grid over its own samples; coincident
// samples left over-full; the same lists at 0, 1, 2 and 7 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <glm/common.hpp>

#include "shading/techniques/irregular_lists.h"

namespace {

namespace tech = shading::tech;

// A sparse spread over [0, 100]² and a dense patch of about `dense` samples in [10, 10.5]², interleaved: the patch
// crowds a few top cells, as the ground at a grazing sun crowds a strip of the light's view.
struct Samples {
  std::vector<glm::dvec2> uv;
  std::vector<double> key;
  glm::dvec2 lo{1e300}, hi{-1e300};
};
Samples spread_and_patch(size_t sparse, size_t dense) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 100.0), p(10.0, 10.5), k(-5.0, 5.0);
  Samples s;
  for (size_t i = 0; i < sparse + dense; ++i) {
    const bool in_patch = i % (sparse / dense + 1) == 0;
    s.uv.push_back(in_patch ? glm::dvec2(p(rng), p(rng)) : glm::dvec2(u(rng), u(rng)));
    s.key.push_back(k(rng));
    s.lo = glm::min(s.lo, s.uv.back()), s.hi = glm::max(s.hi, s.uv.back());
  }
  return s;
}

// The cell of grid g that holds p, as a box grown by a thousandth of a cell.
bool in_cell(const tech::Grid& g, int x, int y, glm::dvec2 p) {
  const glm::dvec2 a = g.lo + g.cell * glm::dvec2(x, y) - 1e-3 * g.cell, b = a + 1.002 * g.cell;
  return p.x >= a.x && p.y >= a.y && p.x <= b.x && p.y <= b.y;
}

TEST(IrregularLists, EverySampleOnceInOrderInsideItsCell) {
  const Samples s = spread_and_patch(20000, 5000);
  raster::ThreadPool pool(2);
  const tech::SampleLists L = tech::build_sample_lists(s.uv, s.key, s.lo, s.hi, 16, 4096, pool);
  ASSERT_EQ(L.sorted.size(), s.uv.size());
  EXPECT_GT(L.split_cells, 0u);  // the patch crowds its top cells past 16 samples
  EXPECT_LE(L.max_in_leaf, 16u);
  EXPECT_EQ(L.overfull_samples, 0u);
  std::vector<int> seen(s.uv.size(), 0);
  size_t listed = 0;
  for (size_t c = 0; c < L.top.cells(); ++c) {
    const int tx = int(c % size_t(L.top.nx)), ty = int(c / size_t(L.top.nx));
    double min_key = 1e300;
    for (uint32_t l = L.top_leaf[c]; l < L.top_leaf[c + 1]; ++l) {
      double leaf_min = 1e300;
      for (uint32_t k = L.leaf_start[l]; k < L.leaf_start[l + 1]; ++k) {
        const uint32_t i = L.sorted[k];
        ++seen[i], ++listed;
        if (k > L.leaf_start[l]) {
          EXPECT_LT(L.sorted[k - 1], i) << "leaf " << l << " out of sample order";
        }
        EXPECT_TRUE(in_cell(L.top, tx, ty, s.uv[i])) << "sample " << i << " outside top cell " << c;
        if (L.split[c] >= 0) {
          const tech::Grid& g = L.subs[size_t(L.split[c])];
          const int q = int(l - L.top_leaf[c]);
          EXPECT_TRUE(in_cell(g, q % g.nx, q / g.nx, s.uv[i])) << "sample " << i << " outside its split cell";
        }
        leaf_min = std::min(leaf_min, s.key[i]);
      }
      if (L.leaf_start[l] < L.leaf_start[l + 1]) {
        EXPECT_EQ(L.leaf_min_key[l], leaf_min);
      }
      min_key = std::min(min_key, leaf_min);
    }
    if (L.top_leaf[c] < L.top_leaf[c + 1]) {
      EXPECT_EQ(L.top_min_key[c], min_key);
    }
  }
  EXPECT_EQ(listed, s.uv.size());
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(s.uv.size()));
}

TEST(IrregularLists, CoincidentSamplesStayInOneOverFullCell) {
  Samples s = spread_and_patch(1000, 10);
  for (int i = 0; i < 100; ++i) s.uv.emplace_back(50.0, 50.0), s.key.push_back(0.0);
  raster::ThreadPool pool(0);
  const tech::SampleLists L = tech::build_sample_lists(s.uv, s.key, s.lo, s.hi, 8, 4096, pool);
  EXPECT_GE(L.max_in_leaf, 100u);
  EXPECT_GE(L.overfull_samples, 100u);
}

TEST(IrregularLists, SameListsAtAnyThreadCount) {
  const Samples s = spread_and_patch(30000, 20000);
  std::vector<uint32_t> first_sorted, first_start;
  for (int threads : {0, 1, 2, 7}) {
    raster::ThreadPool pool(threads);
    const tech::SampleLists L = tech::build_sample_lists(s.uv, s.key, s.lo, s.hi, 4, 4096, pool);
    if (threads == 0) {
      first_sorted = L.sorted, first_start = L.leaf_start;
      EXPECT_GT(L.split_cells, 10u);
      continue;
    }
    EXPECT_EQ(L.sorted, first_sorted) << threads << " threads";
    EXPECT_EQ(L.leaf_start, first_start) << threads << " threads";
  }
}

}  // namespace
