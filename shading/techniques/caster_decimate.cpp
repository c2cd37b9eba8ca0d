// Vertex clustering (see caster_decimate.h).
#include "shading/techniques/caster_decimate.h"

#include <cmath>
#include <unordered_map>

#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

struct CellHash {
  size_t operator()(const glm::ivec3& c) const {
    uint64_t h = uint64_t(uint32_t(c.x)) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(uint32_t(c.y)) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= uint64_t(uint32_t(c.z)) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return size_t(h);
  }
};

}  // namespace

DecimatedMesh cluster_vertices(std::span<const glm::vec3> positions, std::span<const uint32_t> indices, float cell) {
  DecimatedMesh out;
  if (!(cell > 0.0f) || !std::isfinite(cell)) {
    out.positions.assign(positions.begin(), positions.end());
    out.indices.assign(indices.begin(), indices.end());
    return out;
  }
  std::unordered_map<glm::ivec3, uint32_t, CellHash> cells;
  std::vector<uint32_t> cluster(positions.size());
  std::vector<glm::dvec3> sum;
  std::vector<uint32_t> count;
  const double inv = 1.0 / double(cell);
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    const glm::ivec3 c(int(std::floor(double(p.x) * inv)), int(std::floor(double(p.y) * inv)),
                       int(std::floor(double(p.z) * inv)));
    const auto [it, fresh] = cells.try_emplace(c, uint32_t(sum.size()));
    if (fresh) sum.emplace_back(0.0), count.push_back(0);
    cluster[i] = it->second;
    sum[it->second] += glm::dvec3(p);
    ++count[it->second];
  }
  out.positions.resize(sum.size());
  for (size_t k = 0; k < sum.size(); ++k) out.positions[k] = glm::vec3(sum[k] / double(count[k]));
  out.indices.reserve(indices.size());
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = cluster[indices[t]], b = cluster[indices[t + 1]], c = cluster[indices[t + 2]];
    if (a == b || b == c || a == c) continue;
    out.indices.insert(out.indices.end(), {a, b, c});
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
