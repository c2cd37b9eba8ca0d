// The irregular z-buffer's list building (irregular_grid.h): the camera's shadow samples, already projected into
// the light's view, sorted into the per-cell lists of a two-level grid fitted to where they lie. A top grid spans
// the samples' bounds; a top cell holding more than a bound of samples gets its own grid over its own samples'
// bounds, about one sample a cell. Both levels are counting sorts in sample order (the top one serial, the
// split cells' in parallel, each written by one worker), so the lists are the same at any thread count.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/thread_pool.h"

namespace shading::tech {

// A uniform grid over a rectangle of the light's view; a point outside it goes to the nearest edge cell.
struct Grid {
  glm::dvec2 lo{0.0}, cell{1.0}, inv_cell{1.0};
  int nx = 1, ny = 1;
  size_t cells() const { return size_t(nx) * size_t(ny); }
  static int clamp_index(double f, int n) {
    if (!(f >= 0.0)) return 0;  // also NaN
    return f >= double(n - 1) ? n - 1 : int(f);
  }
  int column(double u) const { return clamp_index(std::floor((u - lo.x) * inv_cell.x), nx); }
  int row(double v) const { return clamp_index(std::floor((v - lo.y) * inv_cell.y), ny); }
  int index(glm::dvec2 p) const { return row(p.y) * nx + column(p.x); }
  glm::dvec2 hi() const { return lo + cell * glm::dvec2(nx, ny); }
};

// A grid over [lo, hi] with about `cells` square cells, at most `max_side` a side. A side of zero length (the
// samples on a line or at one point) is widened to 10⁻⁶ of the other, or to 10⁻¹² of the rectangle's distance from
// the origin, so that every cell has an area.
Grid fit_grid(glm::dvec2 lo, glm::dvec2 hi, double cells, int max_side);

// The lists. A leaf is a cell that holds a list: each top cell that is not split, each cell of a split one's grid.
struct SampleLists {
  Grid top;
  std::vector<uint32_t> top_leaf;    // top cell c's leaves are [top_leaf[c], top_leaf[c + 1]); none when empty
  std::vector<int32_t> split;        // per top cell: its own grid's index in `subs`, or −1
  std::vector<Grid> subs;
  std::vector<double> top_min_key;   // per top cell: its samples' smallest light key (+∞ when empty)
  std::vector<uint32_t> leaf_start;  // leaf l's samples are sorted[leaf_start[l] .. leaf_start[l + 1])
  std::vector<double> leaf_min_key;
  std::vector<uint32_t> sorted;      // sample indices, leaf by leaf, in sample order within a leaf
  size_t max_in_leaf = 0;            // the fullest leaf
  size_t overfull_samples = 0;       // samples in leaves holding more than the bound
  size_t split_cells = 0;            // top cells with a grid of their own
};

// Sorts the samples (light-view positions `uv`, light keys `key`, all within [lo, hi]) into lists: a top grid of
// about samples / kTopLoad cells, at most `max_side` a side; every top cell holding more than `cell_bound`
// samples split by a grid over its samples' bounds with about one sample a cell, at most `max_side` a side.
// Samples that coincide (or crowd below the split grid's resolution) stay together in an over-full leaf.
SampleLists build_sample_lists(std::span<const glm::dvec2> uv, std::span<const double> key, glm::dvec2 lo,
                               glm::dvec2 hi, int cell_bound, int max_side, raster::ThreadPool& pool);

// Samples per top cell on average: the top grid is coarse, so that a caster's footprint walks few empty cells;
// the split grids give the dense places their resolution.
inline constexpr double kTopLoad = 4.0;

}  // namespace shading::tech
