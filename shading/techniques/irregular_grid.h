// The irregular z-buffer's light-space pass (irregular.h): the camera's shadow samples projected from the light
// into the per-cell sample lists of a two-level grid (list building, irregular_lists.h), every caster triangle
// rasterized conservatively over those cells (caster rasterization), and each listed sample of a touched cell
// tested exactly against the triangle (sample tests, irregular_ray.h). Runs on the pipeline's worker pool
// (raster/thread_pool.h) in bands of top-grid rows, each band written by one worker; a sample's answer is an OR
// over triangles, so the result is the same at any thread count.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/thread_pool.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The light as the grid sees it. Directional: parallel projection along `axis` (the way light travels); spot:
// central projection from `position` onto the plane one metre down `axis`. `right`, `up` and `axis` are an
// orthonormal basis.
struct IrregularLight {
  bool spot = false;
  glm::dvec3 position{0.0};
  glm::dvec3 axis{0.0, -1.0, 0.0}, right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0};
};
IrregularLight irregular_light(const LightDesc& light);

// How the grid is sized: a top grid over the samples' light-space bounds with a few samples per cell, at most
// `max_side` cells a side; a top cell holding more than `cell_bound` samples gets its own grid over its samples'
// bounds with fewer a cell (irregular_lists.h), at most `max_side` a side. Samples that still crowd one cell (they coincide, or
// lie closer than that grid resolves) stay in an over-full cell: they are still tested exactly, only slower, and
// counted in GridStats::overfull_samples.
struct GridSettings {
  int cell_bound = 64;
  int max_side = 4096;
};

// What the pass did, for --stats and --json: the three steps' costs and the counts behind them.
struct GridStats {
  double list_ms = 0;    // projection, grid sizing, per-cell lists (wall time)
  double raster_ms = 0;  // caster setup and binning (wall) + conservative rasterization (worker time)
  double test_ms = 0;    // exact sample tests (worker time)
  size_t samples = 0, cells_x = 0, cells_y = 0;  // the top grid's sides
  size_t split_cells = 0;                        // top cells with a grid of their own
  size_t max_in_cell = 0, overfull_samples = 0;  // the fullest list; samples in lists over the bound
  size_t pairs = 0;      // (triangle, non-empty cell) pairs the rasterization produced
  size_t tests = 0;      // exact sample tests run
};

// Adds one pass's statistics to a sum (sample batches, cube faces): counts and costs add up; the grid's sides
// and the fullest cell are maxima.
void add_grid_stats(GridStats& sum, const GridStats& s);

// For each ray origin (a surface point moved along its normal), whether some caster blocks its ray to the light:
// 1 shadowed, 0 lit, in the order of `origins`.
std::vector<uint8_t> irregular_shadow(const IrregularLight& light, std::span<const glm::vec3> origins,
                                      const CasterGeometry& casters, const GridSettings& settings,
                                      raster::ThreadPool& pool, GridStats& stats);

SHADOWLAB_ISA_END
}  // namespace shading::tech
