// The irregular z-buffer's light-space pass (see irregular_grid.h): list building, caster rasterization over the
// grid, exact sample tests.
#include "shading/techniques/irregular_grid.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "shading/techniques/irregular_lists.h"
#include "shading/techniques/irregular_ray.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

// The casters as one indexable list of triangles: the opaque soup's, then each masked material's with its
// texture coordinates and alpha test.
class CasterTriangles {
 public:
  explicit CasterTriangles(const CasterGeometry& c) : c_(c), opaque_(c.indices.size() / 3) {
    size_t n = opaque_;
    for (const MaskedCasters& m : c.masked) first_.push_back(n), n += m.indices.size() / 3;
    size_ = n;
  }
  size_t size() const { return size_; }
  std::array<glm::dvec3, 3> corners(size_t t) const {
    if (t < opaque_)
      return {glm::dvec3(c_.positions[c_.indices[3 * t]]), glm::dvec3(c_.positions[c_.indices[3 * t + 1]]),
              glm::dvec3(c_.positions[c_.indices[3 * t + 2]])};
    const auto [m, k] = masked(t);
    const MaskedCasters& mc = c_.masked[m];
    return {glm::dvec3(mc.vertices[mc.indices[3 * k]].position),
            glm::dvec3(mc.vertices[mc.indices[3 * k + 1]].position),
            glm::dvec3(mc.vertices[mc.indices[3 * k + 2]].position)};
  }
  // Whether triangle t blocks at the hit with barycentrics `bary` (of its corners a, b, c): always for an opaque
  // one; for a masked one where its alpha at the interpolated texture coordinates passes the cutoff.
  bool passes_alpha(size_t t, const glm::dvec3& bary) const {
    if (t < opaque_) return true;
    const auto [m, k] = masked(t);
    const MaskedCasters& mc = c_.masked[m];
    if (!mc.alpha) return true;
    const glm::vec2 st = float(bary.x) * mc.vertices[mc.indices[3 * k]].st +
                         float(bary.y) * mc.vertices[mc.indices[3 * k + 1]].st +
                         float(bary.z) * mc.vertices[mc.indices[3 * k + 2]].st;
    return !mc.alpha->discarded_at(st);
  }

 private:
  std::pair<size_t, size_t> masked(size_t t) const {
    size_t m = first_.size() - 1;
    while (first_[m] > t) --m;
    return {m, t - first_[m]};
  }
  const CasterGeometry& c_;
  size_t opaque_, size_ = 0;
  std::vector<size_t> first_;  // index of each masked material's first triangle
};

}  // namespace

IrregularLight irregular_light(const LightDesc& light) {
  IrregularLight l;
  l.spot = light.type == LightType::spot;
  l.position = glm::dvec3(light.position);
  l.axis = glm::dvec3(light.direction);  // unit already (resolve_light normalises it): the rays' exact direction
  const glm::dvec3 a = glm::normalize(l.axis);
  const glm::dvec3 helper = std::abs(a.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  l.right = glm::normalize(glm::cross(helper, a));
  l.up = glm::cross(a, l.right);
  return l;
}

namespace {

using Clock = std::chrono::steady_clock;
double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

constexpr size_t kChunk = 16384;  // samples or triangles per pool index in the per-item steps
constexpr int kBandRows = 4;      // grid rows per band: one pool index of the rasterization and tests

// Where a point lands on the grid's plane. Directional: its coordinates across the light's axis; spot: the
// central projection (tangents), defined in front of the light only.
glm::dvec2 project(const IrregularLight& l, const glm::dvec3& p) {
  if (!l.spot) return {glm::dot(p, l.right), glm::dot(p, l.up)};
  const glm::dvec3 r = p - l.position;
  const double z = glm::dot(r, l.axis);
  return {glm::dot(r, l.right) / z, glm::dot(r, l.up) / z};
}

// Nearness to the light along its rays: a triangle can block a sample only if some point of it has a larger key
// than the sample (it lies between the sample and the light).
double light_key(const IrregularLight& l, const glm::dvec3& p) {
  return l.spot ? -glm::dot(p - l.position, l.axis) : -glm::dot(p, l.axis);
}

double key_slack(double k) { return 1e-9 * (1.0 + std::abs(k)); }

// A caster triangle's footprint on the grid: its projection (a spot light's triangle clipped in front of the
// light first, so up to four corners), counter-clockwise, and the cells its bounding box (grown by `margin`)
// touches. n = 0: the triangle cannot block any sample.
struct Footprint {
  std::array<glm::dvec2, 4> p{};
  int n = 0;
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // the top grid's cells under its box grown by the top margin
  glm::dvec2 lo{0.0}, hi{0.0};           // its box
  double max_key = 0.0;
};

// The triangle's corners clipped to the half-space z >= z_min in front of a spot light, projected.
int clipped_projection(const IrregularLight& l, const std::array<glm::dvec3, 3>& v, double z_min,
                       std::array<glm::dvec2, 4>& out) {
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& a = v[size_t(i)];
    const glm::dvec3& b = v[size_t((i + 1) % 3)];
    const double za = glm::dot(a - l.position, l.axis), zb = glm::dot(b - l.position, l.axis);
    if (za >= z_min) out[size_t(n++)] = project(l, a);
    if ((za >= z_min) != (zb >= z_min)) {
      const double t = (z_min - za) / (zb - za);
      out[size_t(n++)] = project(l, a + t * (b - a));
    }
  }
  return n;
}

Footprint footprint(const IrregularLight& l, const std::array<glm::dvec3, 3>& v, const Grid& g, double min_key,
                    double z_min, double margin) {
  Footprint f;
  f.max_key = std::max({light_key(l, v[0]), light_key(l, v[1]), light_key(l, v[2])});
  if (f.max_key < min_key - key_slack(min_key)) return f;  // wholly beyond every sample, seen from the light
  int n = 3;
  if (l.spot) {
    n = clipped_projection(l, v, z_min, f.p);
  } else {
    for (size_t i = 0; i < 3; ++i) f.p[i] = project(l, v[i]);
  }
  if (n < 3) return f;
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 &a = f.p[size_t(i)], &b = f.p[size_t((i + 1) % n)];
    area += a.x * b.y - a.y * b.x;
  }
  if (!(area != 0.0) || !std::isfinite(area)) return f;  // seen edge-on: no ray passes through its inside
  if (area < 0.0) std::reverse(f.p.begin(), f.p.begin() + n);
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (int i = 0; i < n; ++i) lo = glm::min(lo, f.p[size_t(i)]), hi = glm::max(hi, f.p[size_t(i)]);
  f.lo = lo, f.hi = hi;
  lo -= margin, hi += margin;
  const glm::dvec2 g_hi = g.hi();
  if (hi.x < g.lo.x || hi.y < g.lo.y || lo.x > g_hi.x || lo.y > g_hi.y) return f;
  f.n = n;
  f.x0 = g.column(lo.x), f.x1 = g.column(hi.x);
  f.y0 = g.row(lo.y), f.y1 = g.row(hi.y);
  return f;
}

// Conservative: false only where the cell (grown by margin) lies wholly outside one of the footprint's edges.
bool overlaps(const Footprint& f, const Grid& g, int x, int y, double margin) {
  const glm::dvec2 half = 0.5 * g.cell;
  const glm::dvec2 centre = g.lo + g.cell * glm::dvec2(double(x) + 0.5, double(y) + 0.5);
  for (int i = 0; i < f.n; ++i) {
    const glm::dvec2 &a = f.p[size_t(i)], &b = f.p[size_t((i + 1) % f.n)];
    const glm::dvec2 inward(a.y - b.y, b.x - a.x);  // counter-clockwise: the inside is to the left
    const double reach = std::abs(inward.x) * (half.x + margin) + std::abs(inward.y) * (half.y + margin);
    if (glm::dot(inward, centre - a) + reach < 0.0) return false;
  }
  return true;
}

}  // namespace

void add_grid_stats(GridStats& sum, const GridStats& s) {
  sum.list_ms += s.list_ms, sum.raster_ms += s.raster_ms, sum.test_ms += s.test_ms;
  sum.samples += s.samples, sum.pairs += s.pairs, sum.tests += s.tests;
  sum.split_cells += s.split_cells, sum.overfull_samples += s.overfull_samples;
  sum.max_in_cell = std::max(sum.max_in_cell, s.max_in_cell);
  sum.cells_x = std::max(sum.cells_x, s.cells_x), sum.cells_y = std::max(sum.cells_y, s.cells_y);
}

std::vector<uint8_t> irregular_shadow(const IrregularLight& light, std::span<const glm::vec3> origins,
                                      const CasterGeometry& casters, const GridSettings& settings,
                                      raster::ThreadPool& pool, GridStats& stats) {
  stats = GridStats{};
  const size_t n = origins.size();
  stats.samples = n;
  std::vector<uint8_t> result(n, 0);
  if (n == 0) return result;

  // ---- List building: project (parallel, with each chunk's bounds), then the two-level lists.
  const auto t_list = Clock::now();
  std::vector<glm::dvec2> uv(n);
  std::vector<double> key(n);
  const size_t sample_chunks = (n + kChunk - 1) / kChunk;
  struct Bounds {
    glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    double min_key = std::numeric_limits<double>::infinity(), max_key = -std::numeric_limits<double>::infinity();
  };
  std::vector<Bounds> chunk_bounds(sample_chunks);
  pool.parallel_for(sample_chunks, [&](size_t c) {
    Bounds b;
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
      const glm::dvec3 o(origins[i]);
      uv[i] = project(light, o);
      key[i] = light_key(light, o);
      b.lo = glm::min(b.lo, uv[i]), b.hi = glm::max(b.hi, uv[i]);
      b.min_key = std::min(b.min_key, key[i]), b.max_key = std::max(b.max_key, key[i]);
    }
    chunk_bounds[c] = b;
  });
  Bounds all;  // minima and maxima: the same whichever worker ran a chunk
  for (const Bounds& b : chunk_bounds) {
    all.lo = glm::min(all.lo, b.lo), all.hi = glm::max(all.hi, b.hi);
    all.min_key = std::min(all.min_key, b.min_key), all.max_key = std::max(all.max_key, b.max_key);
  }
  const glm::dvec2 lo = all.lo, hi = all.hi;
  const double min_key = all.min_key;
  const double min_z = light.spot ? -all.max_key : 0.0;  // spot: the nearest sample's depth
  const SampleLists lists =
      build_sample_lists(uv, key, lo, hi, settings.cell_bound, std::max(1, settings.max_side), pool);
  const Grid& g = lists.top;
  std::vector<glm::vec3> sorted_origin(n);
  pool.parallel_for(sample_chunks, [&](size_t c) {
    for (size_t s = c * kChunk; s < std::min(n, (c + 1) * kChunk); ++s) sorted_origin[s] = origins[lists.sorted[s]];
  });
  stats.cells_x = size_t(g.nx), stats.cells_y = size_t(g.ny);
  stats.max_in_cell = lists.max_in_leaf, stats.overfull_samples = lists.overfull_samples;
  stats.split_cells = lists.split_cells;
  const auto t_raster = Clock::now();
  stats.list_ms = ms_between(t_list, t_raster);

  // ---- Caster setup: each triangle's footprint, then the triangles of each band of grid rows, in order. The
  // opaque triangles first, then each masked material's, which block only where their alpha test passes at the
  // ray's hit (level 0, as the reference's occlusion filter reads them).
  const CasterTriangles tris(casters);
  const size_t ntri = tris.size();
  // Cells are grown by 10⁻³ of a cell, plus 10⁻¹² of the view's scale for the rounding of the projections.
  const double slack = 1e-12 * (1.0 + glm::length(lo) + glm::length(hi));
  const double margin = 1e-3 * std::min(g.cell.x, g.cell.y) + slack;
  const double z_min = 0.5e-5 * min_z;  // the reference's rays stop 10⁻⁵ of their length short of the light
  std::vector<Footprint> feet(ntri);
  pool.parallel_for((ntri + kChunk - 1) / kChunk, [&](size_t c) {
    for (size_t t = c * kChunk; t < std::min(ntri, (c + 1) * kChunk); ++t) {
      feet[t] = footprint(light, tris.corners(t), g, min_key, z_min, margin);
    }
  });
  const size_t nbands = size_t((g.ny + kBandRows - 1) / kBandRows);
  std::vector<uint32_t> band_start(nbands + 1, 0);
  for (const Footprint& f : feet)
    if (f.n) for (int b = f.y0 / kBandRows; b <= f.y1 / kBandRows; ++b) ++band_start[size_t(b) + 1];
  for (size_t b = 0; b < nbands; ++b) band_start[b + 1] += band_start[b];
  std::vector<uint32_t> band_tris(band_start[nbands]);
  {
    std::vector<uint32_t> cursor(band_start.begin(), band_start.end() - 1);
    for (size_t t = 0; t < ntri; ++t)
      if (feet[t].n)
        for (int b = feet[t].y0 / kBandRows; b <= feet[t].y1 / kBandRows; ++b) band_tris[cursor[size_t(b)]++] = uint32_t(t);
  }
  const double setup_ms = ms_between(t_raster, Clock::now());

  // ---- Per band: rasterize its triangles over its non-empty cells, then test the listed samples exactly.
  std::vector<uint8_t> shadowed(n, 0);  // per sorted sample
  struct BandCost {
    double raster_ms = 0, test_ms = 0;
    size_t pairs = 0, tests = 0;
  };
  std::vector<BandCost> cost(nbands);
  pool.parallel_for(nbands, [&](size_t b) {
    const auto t0 = Clock::now();
    const int row_lo = int(b) * kBandRows, row_hi = std::min(g.ny - 1, row_lo + kBandRows - 1);
    std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (triangle, leaf)
    auto reaches = [](const Footprint& f, double cell_min_key) {  // some of the triangle is nearer the light
      return f.max_key >= cell_min_key - key_slack(cell_min_key);
    };
    for (uint32_t k = band_start[b]; k < band_start[b + 1]; ++k) {
      const uint32_t t = band_tris[k];
      const Footprint& f = feet[t];
      for (int y = std::max(f.y0, row_lo); y <= std::min(f.y1, row_hi); ++y)
        for (int x = f.x0; x <= f.x1; ++x) {
          const size_t c = size_t(y) * size_t(g.nx) + size_t(x);
          if (lists.top_leaf[c] == lists.top_leaf[c + 1] || !reaches(f, lists.top_min_key[c])) continue;
          if (!overlaps(f, g, x, y, margin)) continue;
          if (lists.split[c] < 0) {
            pairs.emplace_back(t, lists.top_leaf[c]);
            continue;
          }
          // A split cell: the same over its own grid's cells under the footprint's box.
          const Grid& sg = lists.subs[size_t(lists.split[c])];
          const double sm = 1e-3 * std::min(sg.cell.x, sg.cell.y) + slack;
          const glm::dvec2 flo = f.lo - sm, fhi = f.hi + sm, shi = sg.hi();
          if (fhi.x < sg.lo.x || fhi.y < sg.lo.y || flo.x > shi.x || flo.y > shi.y) continue;
          for (int sy = sg.row(flo.y); sy <= sg.row(fhi.y); ++sy)
            for (int sx = sg.column(flo.x); sx <= sg.column(fhi.x); ++sx) {
              const uint32_t leaf = lists.top_leaf[c] + uint32_t(sy * sg.nx + sx);
              if (lists.leaf_start[leaf] == lists.leaf_start[leaf + 1]) continue;
              if (!reaches(f, lists.leaf_min_key[leaf]) || !overlaps(f, sg, sx, sy, sm)) continue;
              pairs.emplace_back(t, leaf);
            }
        }
    }
    const auto t1 = Clock::now();
    size_t tests = 0;
    for (const auto& [t, leaf] : pairs) {
      const std::array<glm::dvec3, 3> v = tris.corners(t);
      const glm::dvec3 &a = v[0], &bv = v[1], &cv = v[2];
      for (uint32_t s = lists.leaf_start[leaf]; s < lists.leaf_start[leaf + 1]; ++s) {
        if (shadowed[s]) continue;
        ShadowRay r;
        r.origin = glm::dvec3(sorted_origin[s]);
        if (light.spot) {
          r.dir = light.position - r.origin;
          r.t_max = 1.0 - 1e-5;
        } else {
          r.dir = -light.axis;
          r.t_max = std::numeric_limits<double>::infinity();
        }
        ++tests;
        glm::dvec3 bary;
        if (blocks(a, bv, cv, r, &bary) && tris.passes_alpha(t, bary)) shadowed[s] = 1;
      }
    }
    cost[b] = BandCost{ms_between(t0, t1), ms_between(t1, Clock::now()), pairs.size(), tests};
  });
  stats.raster_ms = setup_ms;
  for (const BandCost& c : cost) {
    stats.raster_ms += c.raster_ms, stats.test_ms += c.test_ms;
    stats.pairs += c.pairs, stats.tests += c.tests;
  }
  for (size_t s = 0; s < n; ++s) result[lists.sorted[s]] = shadowed[s];
  return result;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
