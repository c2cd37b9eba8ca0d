// The irregular z-buffer's samples, visibility buffer and LightShadow (see irregular.h).
#include "shading/techniques/irregular.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shading/techniques/irregular_cube.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

// Direct3D's standard 8× pattern, in sixteenths of a pixel from the centre.
const glm::vec2 kEight[8] = {{1 / 16.f, -3 / 16.f}, {-1 / 16.f, 3 / 16.f}, {5 / 16.f, 1 / 16.f},
                                 {-3 / 16.f, -5 / 16.f}, {-5 / 16.f, 5 / 16.f}, {-7 / 16.f, -1 / 16.f},
                                 {3 / 16.f, 7 / 16.f},   {7 / 16.f, -7 / 16.f}};

// The rank-1 lattice ((i + ½) / 32, ((7 i mod 32) + ½) / 32) − ½: generator 7 gives the largest smallest
// (toroidal) distance between two of the 32 points, 0.177 pixel.
std::array<glm::vec2, 32> lattice32() {
  std::array<glm::vec2, 32> p{};
  for (int i = 0; i < 32; ++i)
    p[size_t(i)] = glm::vec2((float(i) + 0.5f) / 32.0f - 0.5f, (float((7 * i) % 32) + 0.5f) / 32.0f - 0.5f);
  return p;
}
const glm::vec2 kCentre[1] = {{0.0f, 0.0f}};

// Samples are projected, sorted and tested in batches: up to this many of each pixel's samples, over a band of
// rows holding at most IrregularSettings::max_batch_samples of them. Each sample's answer is exact and independent
// of the others (the grid only finds candidate triangles), so the batching changes the statistics, never the
// visibility. Unbounded, a 16384 x 16384 frame in one batch needed 24 GB and was killed by the kernel.
constexpr size_t kSamplesPerBatch = 8;


}  // namespace

std::span<const glm::vec2> pixel_sample_offsets(int samples_per_pixel) {
  switch (samples_per_pixel) {
    case 1: return kCentre;
    case 8: return kEight;
    case 32: {
      // Built on first use, not at start-up: a namespace-scope initialiser would run this set's code before
      // the entry point has chosen the set (raster/simd/isa.h).
      static const std::array<glm::vec2, 32> lattice = lattice32();
      return lattice;
    }
    default: return {};
  }
}

glm::vec3 footprint_point(const glm::dmat4& inv_view_proj, glm::vec2 size, glm::vec2 frag, glm::vec2 offset,
                          glm::vec3 p, glm::vec3 n) {
  const glm::dvec2 ndc = 2.0 * (glm::dvec2(frag) + glm::dvec2(offset)) / glm::dvec2(size) - 1.0;
  const glm::dvec4 a = inv_view_proj * glm::dvec4(ndc, -1.0, 1.0), b = inv_view_proj * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 near = glm::dvec3(a) / a.w, dir = glm::dvec3(b) / b.w - near;
  const double along = glm::dot(glm::dvec3(n), dir);
  if (!(std::abs(along) > 0.0)) return p;
  const double t = glm::dot(glm::dvec3(n), glm::dvec3(p) - near) / along;
  if (!(t > 0.0) || !std::isfinite(t)) return p;
  return glm::vec3(near + t * dir);
}

bool shadow_origin(const LightDesc& light, glm::vec3 p, glm::vec3 n, float epsilon, glm::vec3& origin) {
  glm::vec3 dir = -light.direction;
  if (light.type != LightType::directional) {  // spot or point: the range, and a spot's cone
    const glm::vec3 d = light.position - p;
    const float dist = glm::length(d);
    if (!(dist > 0.0f)) return false;
    if (light.range > 0.0f && dist >= light.range) return false;
    dir = d / dist;
    if (light.type == LightType::spot && glm::dot(-dir, light.direction) < std::cos(light.outer_angle)) return false;
  }
  if (!(glm::dot(n, dir) > 0.0f)) return false;  // the surface faces away: it shadows itself
  origin = p + epsilon * n;
  return true;
}

IrregularBuffer irregular_visibility(const CameraSurface& surface, const LightDesc& light,
                                     const glm::mat4& camera_view_proj, const IrregularSettings& settings,
                                     const CasterGeometry& casters, raster::ThreadPool& pool) {
  const std::span<const glm::vec2> offsets = pixel_sample_offsets(settings.samples_per_pixel);
  const size_t pixels = surface.covered.size(), spp = offsets.size();
  IrregularBuffer out;
  out.visibility.assign(pixels, 1.0f);
  if (spp == 0) return out;
  const glm::dmat4 inv = glm::inverse(glm::dmat4(camera_view_proj));
  const glm::vec2 size(float(surface.width), float(surface.height));
  const IrregularLight il = irregular_light(light);
  std::vector<uint8_t> lit(pixels, 0);
  const size_t width = size_t(std::max(surface.width, 1));
  for (size_t k0 = 0; k0 < spp; k0 += kSamplesPerBatch) {
    const size_t group = std::min(kSamplesPerBatch, spp - k0);
    const size_t band_rows = std::max<size_t>(1, std::max<size_t>(settings.max_batch_samples, 1) / (width * group));
    for (size_t y0 = 0; y0 < size_t(surface.height); y0 += band_rows) {
      const size_t y1 = std::min(size_t(surface.height), y0 + band_rows);
      const size_t first = y0 * width, band_pixels = (y1 - y0) * width;
      // Each pixel's samples of this batch, in pixel order then sample order; then the reached ones packed.
      std::vector<glm::vec3> dense(band_pixels * group);
      std::vector<uint8_t> reached(band_pixels * group, 0);
      pool.parallel_for(y1 - y0, [&](size_t row) {
        const int y = int(y0 + row);
        for (int x = 0; x < surface.width; ++x) {
          const size_t p = surface.index(x, y), q = p - first;
          if (!surface.covered[p]) continue;
          const glm::vec2 frag(float(x) + 0.5f, float(y) + 0.5f);
          for (size_t j = 0; j < group; ++j) {
            const glm::vec3 pos = spp == 1 ? surface.position[p]
                                           : footprint_point(inv, size, frag, offsets[k0 + j], surface.position[p],
                                                             surface.normal[p]);
            reached[q * group + j] =
                shadow_origin(light, pos, surface.normal[p], surface.epsilon, dense[q * group + j]) ? 1 : 0;
          }
        }
      });
      std::vector<glm::vec3> origins;
      std::vector<uint32_t> owner;
      for (size_t i = 0; i < dense.size(); ++i)
        if (reached[i]) origins.push_back(dense[i]), owner.push_back(uint32_t(first + i / group));
      dense = {};
      reached = {};
      GridStats st;
      const std::vector<uint8_t> shadowed =
          light.type == LightType::point
              ? irregular_cube_shadow(light.position, origins, casters, settings.grid, pool, st)
              : irregular_shadow(il, origins, casters, settings.grid, pool, st);
      add_grid_stats(out.stats, st);
      for (size_t i = 0; i < origins.size(); ++i)
        if (!shadowed[i]) ++lit[owner[i]];
    }
  }
  for (size_t p = 0; p < pixels; ++p)
    if (surface.covered[p]) out.visibility[p] = float(lit[p]) / float(spp);
  return out;
}

namespace {

using Clock = std::chrono::steady_clock;

// The technique as a LightShadow: built from the camera's surface, read per fragment from the buffer.
class IrregularShadow final : public LightShadow {
 public:
  IrregularShadow(const LightDesc& light, const IrregularSettings& settings, const PlanInputs& in)
      : light_(light), settings_(settings), surface_(in.surface), view_proj_(in.camera_view_proj) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& casters) override {
    const auto t0 = Clock::now();
    const CameraSurface& s = surface_();  // the frame's pre-pass, run by the first light that asks
    const auto t1 = Clock::now();
    surface_ms_ = std::chrono::duration<double, std::milli>(t1 - t0).count();
    width_ = s.width, height_ = s.height;
    buffer_ = irregular_visibility(s, light_, view_proj_, settings_, casters, renderer.pool());
    return {};  // no draw: the casters are rasterized over the sample grid, not into a target
  }

  // The buffer at each point's pixel. The camera pass shades the pre-pass's surface point at each pixel (the
  // same draws); a fragment that a later one covers reads that pixel's answer, which its overwriting hides.
  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    for (size_t i = 0; i < q.size(); ++i) {
      const int x = int(q[i].frag.x), y = int(q[i].frag.y);
      vis[i] = x >= 0 && y >= 0 && x < width_ && y < height_
                   ? buffer_.visibility[size_t(y) * size_t(width_) + size_t(x)]
                   : 1.0f;
    }
  }

  std::vector<MapRecord> maps() const override { return {}; }  // nothing to export: there is no map

  std::vector<TechniqueStat> stats() const override {
    const GridStats& g = buffer_.stats;
    return {{"surface_ms", surface_ms_},
            {"list_ms", g.list_ms},
            {"raster_ms", g.raster_ms},
            {"test_ms", g.test_ms},
            {"samples", double(g.samples)},
            {"cells_x", double(g.cells_x)},
            {"cells_y", double(g.cells_y)},
            {"split_cells", double(g.split_cells)},
            {"max_in_cell", double(g.max_in_cell)},
            {"overfull_samples", double(g.overfull_samples)},
            {"pairs", double(g.pairs)},
            {"tests", double(g.tests)}};
  }

 private:
  LightDesc light_;
  IrregularSettings settings_;
  std::function<const CameraSurface&()> surface_;
  glm::mat4 view_proj_;
  int width_ = 0, height_ = 0;
  IrregularBuffer buffer_;
  double surface_ms_ = 0.0;
};

}  // namespace

std::unique_ptr<LightShadow> plan_irregular(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in) {
  const Params p(config);
  IrregularSettings s;
  const double spp = p.number("samples_per_pixel");
  if (pixel_sample_offsets(int(spp)).empty())
    throw TechniqueError(p.where("samples_per_pixel") + ": " + std::to_string(int(spp)) + " is not 1, 8 or 32");
  s.samples_per_pixel = int(spp);
  s.grid.cell_bound = int(p.number("cell_bound"));
  s.grid.max_side = config.map_size;
  if (!in.surface)
    throw TechniqueError("shadow.technique: irregular needs the camera's visible surface, which this caller does "
                         "not provide (PlanInputs::surface)");
  return std::make_unique<IrregularShadow>(light, s, in);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
