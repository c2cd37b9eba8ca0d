// The irregular z-buffer's list building (irregular_grid.h): the camera's shadow samples, already projected into
// the light's view, sorted into the per-cell lists of a two-level grid fitted to where they lie. A top grid spans
// the samples' bounds; a top cell holding more than a bound of samples gets its own grid over its own samples'
// bounds, with fewer samples a cell. Both levels are counting sorts in sample order (the top one serial, the
// split cells' in parallel, each written by one worker), so the lists are the same at any thread count.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/thread_pool.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

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
// samples split by a grid over its samples' bounds with about split_load(cell_bound) samples a cell, its sides
// doubled while a cell holds more than the bound, up to `max_side` a side and 16 cells a sample. Samples that
// coincide (or crowd below that resolution) stay together in an over-full leaf.
SampleLists build_sample_lists(std::span<const glm::dvec2> uv, std::span<const double> key, glm::dvec2 lo,
                               glm::dvec2 hi, int cell_bound, int max_side, raster::ThreadPool& pool);

// Samples per cell the grids aim at. Each (caster, cell) pair the rasterization makes costs about what a sample
// test does, so cells of one sample are too fine: on duel at 1920x1080 and 8 samples a pixel, one sample a cell
// made 10.0 M pairs and eight 2.4 M, for the same 15.0 M sample tests (the casters that cover many samples, the
// ground under them, dominate the tests whatever the cells). A split cell's grid aims at an eighth of the bound,
// at most eight, so that its cells seldom exceed the bound.
inline constexpr double kTopLoad = 8.0;
inline double split_load(int cell_bound) { return std::clamp(double(cell_bound) / 8.0, 1.0, 8.0); }

SHADOWLAB_ISA_END
}  // namespace shading::tech
