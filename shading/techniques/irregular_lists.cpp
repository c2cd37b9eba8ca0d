// The irregular z-buffer's two-level sample lists (see irregular_lists.h).
#include "shading/techniques/irregular_lists.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

Grid fit_grid(glm::dvec2 lo, glm::dvec2 hi, double cells, int max_side) {
  Grid g;
  g.lo = lo;
  const double big = std::max({hi.x - lo.x, hi.y - lo.y, 1e-12 * (1.0 + glm::length(lo))});
  const glm::dvec2 extent(std::max(hi.x - lo.x, big * 1e-6), std::max(hi.y - lo.y, big * 1e-6));
  const double side = std::sqrt(extent.x * extent.y / std::max(cells, 1.0));
  const double cap = double(std::max(1, max_side));
  g.nx = int(std::clamp(std::ceil(extent.x / side), 1.0, cap));
  g.ny = int(std::clamp(std::ceil(extent.y / side), 1.0, cap));
  g.cell = extent / glm::dvec2(g.nx, g.ny);
  g.inv_cell = 1.0 / g.cell;
  return g;
}

namespace {

constexpr size_t kChunk = 16384;  // samples per pool index
constexpr size_t kCellChunk = 64;  // split cells per pool index
constexpr size_t kMaxSplitCells = 16;  // a split cell's grid has at most this many cells per sample

}  // namespace

SampleLists build_sample_lists(std::span<const glm::dvec2> uv, std::span<const double> key, glm::dvec2 lo,
                               glm::dvec2 hi, int cell_bound, int max_side, raster::ThreadPool& pool) {
  SampleLists L;
  const size_t n = uv.size();
  const size_t bound = size_t(std::max(cell_bound, 1));
  L.top = fit_grid(lo, hi, double(n) / kTopLoad, max_side);
  const Grid& top = L.top;
  const size_t cells = top.cells();

  // Top level: each sample's cell (parallel), then a counting sort in sample order (serial, O(samples + cells)).
  std::vector<uint32_t> cell_of(n);
  pool.parallel_for((n + kChunk - 1) / kChunk, [&](size_t c) {
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) cell_of[i] = uint32_t(top.index(uv[i]));
  });
  std::vector<uint32_t> top_start(cells + 1, 0);
  for (size_t i = 0; i < n; ++i) ++top_start[cell_of[i] + 1];
  // Which cells split, and each top cell's first leaf: none when empty, one when whole, its grid's otherwise
  // (the grids are fitted below, so the leaf numbering waits for their sizes).
  std::vector<uint32_t> to_split;
  L.split.assign(cells, -1);
  for (size_t c = 0; c < cells; ++c)
    if (top_start[c + 1] > bound) L.split[c] = int32_t(to_split.size()), to_split.push_back(uint32_t(c));
  for (size_t c = 0; c < cells; ++c) top_start[c + 1] += top_start[c];
  L.sorted.resize(n);
  {
    std::vector<uint32_t> cursor(top_start.begin(), top_start.end() - 1);
    for (size_t i = 0; i < n; ++i) L.sorted[cursor[cell_of[i]]++] = uint32_t(i);
  }
  cell_of = {};

  // Each split cell's grid over its own samples' bounds (parallel; each writes its own entry). Where the samples
  // crowd part of the cell (a few stray ones widen the bounds), the grid's sides double while a cell holds more
  // than the bound, up to max_side and to kMaxSplitCells cells a sample (coincident samples never part).
  L.subs.resize(to_split.size());
  L.split_cells = to_split.size();
  const size_t split_chunks = (to_split.size() + kCellChunk - 1) / kCellChunk;
  pool.parallel_for(split_chunks, [&](size_t k) {
    std::vector<uint32_t> count;
    for (size_t j = k * kCellChunk; j < std::min(to_split.size(), (k + 1) * kCellChunk); ++j) {
      const uint32_t c = to_split[j];
      const uint32_t s0 = top_start[c], m = top_start[c + 1] - s0;
      glm::dvec2 slo(std::numeric_limits<double>::infinity()), shi(-slo);
      for (uint32_t s = s0; s < s0 + m; ++s) slo = glm::min(slo, uv[L.sorted[s]]), shi = glm::max(shi, uv[L.sorted[s]]);
      Grid g = fit_grid(slo, shi, double(m) / split_load(cell_bound), max_side);
      for (;;) {
        count.assign(g.cells(), 0);
        uint32_t fullest = 0;
        for (uint32_t s = s0; s < s0 + m; ++s) fullest = std::max(fullest, ++count[size_t(g.index(uv[L.sorted[s]]))]);
        const int nx = std::min(2 * g.nx, max_side), ny = std::min(2 * g.ny, max_side);
        if (fullest <= bound || (nx == g.nx && ny == g.ny) || size_t(nx) * size_t(ny) > kMaxSplitCells * m) break;
        const glm::dvec2 extent = g.cell * glm::dvec2(g.nx, g.ny);
        g.nx = nx, g.ny = ny;
        g.cell = extent / glm::dvec2(nx, ny);
        g.inv_cell = 1.0 / g.cell;
      }
      L.subs[j] = g;
    }
  });
  L.top_leaf.assign(cells + 1, 0);
  for (size_t c = 0; c < cells; ++c) {
    const uint32_t count = top_start[c + 1] - top_start[c];
    const size_t leaves = count == 0 ? 0 : L.split[c] < 0 ? 1 : L.subs[size_t(L.split[c])].cells();
    L.top_leaf[c + 1] = L.top_leaf[c] + uint32_t(leaves);
  }
  const size_t nleaves = L.top_leaf[cells];
  L.leaf_start.assign(nleaves + 1, 0);
  L.leaf_start[nleaves] = uint32_t(n);
  for (size_t c = 0; c < cells; ++c)
    if (L.split[c] < 0 && top_start[c + 1] > top_start[c]) L.leaf_start[L.top_leaf[c]] = top_start[c];

  // Second level: each split cell's samples re-sorted by their cell of its grid, in sample order, within the
  // cell's own range of `sorted` (parallel; each range and each leaf entry is written by one worker).
  pool.parallel_for(split_chunks, [&](size_t k) {
    std::vector<uint32_t> local, count, copy;
    for (size_t j = k * kCellChunk; j < std::min(to_split.size(), (k + 1) * kCellChunk); ++j) {
      const uint32_t c = to_split[j];
      const Grid& g = L.subs[j];
      const uint32_t s0 = top_start[c], m = top_start[c + 1] - s0;
      local.resize(m);
      count.assign(g.cells() + 1, 0);
      for (uint32_t s = 0; s < m; ++s) ++count[(local[s] = uint32_t(g.index(uv[L.sorted[s0 + s]]))) + 1];
      for (size_t q = 0; q < g.cells(); ++q) {
        L.leaf_start[L.top_leaf[c] + q] = s0 + count[q];
        count[q + 1] += count[q];
      }
      copy.assign(L.sorted.begin() + s0, L.sorted.begin() + s0 + m);
      for (uint32_t s = 0; s < m; ++s) L.sorted[s0 + count[local[s]]++] = copy[s];
    }
  });

  // Each leaf's and each top cell's smallest key, the fullest leaf and the over-full samples.
  L.leaf_min_key.assign(nleaves, std::numeric_limits<double>::infinity());
  pool.parallel_for((nleaves + kChunk - 1) / kChunk, [&](size_t k) {
    for (size_t l = k * kChunk; l < std::min(nleaves, (k + 1) * kChunk); ++l)
      for (uint32_t s = L.leaf_start[l]; s < L.leaf_start[l + 1]; ++s)
        L.leaf_min_key[l] = std::min(L.leaf_min_key[l], key[L.sorted[s]]);
  });
  L.top_min_key.assign(cells, std::numeric_limits<double>::infinity());
  for (size_t c = 0; c < cells; ++c)
    for (uint32_t l = L.top_leaf[c]; l < L.top_leaf[c + 1]; ++l)
      L.top_min_key[c] = std::min(L.top_min_key[c], L.leaf_min_key[l]);
  for (size_t l = 0; l < nleaves; ++l) {
    const size_t m = L.leaf_start[l + 1] - L.leaf_start[l];
    L.max_in_leaf = std::max(L.max_in_leaf, m);
    if (m > bound) L.overfull_samples += m;
  }
  return L;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
