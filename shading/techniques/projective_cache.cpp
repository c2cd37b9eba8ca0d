// Cache keys and bookkeeping for projective caster maps (see projective_cache.h).
#include "shading/techniques/projective_cache.h"

#include <cstring>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {
// FNV-1a taken eight bytes at a time (then the tail byte by byte): a mesh is hashed every frame it is a
// caster, so this runs at memory speed rather than one multiply per byte.
uint64_t fnv1a(uint64_t h, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = (h ^ w) * 1099511628211ull;
    h ^= h >> 29;
  }
  for (; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}
}  // namespace

uint64_t mesh_content_hash(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
  uint64_t h = 1469598103934665603ull;
  h = fnv1a(h, positions.data(), positions.size_bytes());
  h = fnv1a(h, indices.data(), indices.size_bytes());
  const uint64_t counts[2] = {positions.size(), indices.size()};
  return fnv1a(h, counts, sizeof counts);
}

CasterKey make_caster_key(const ProjectiveLight& light, const ProjectiveSettings& s,
                          std::span<const CasterInstanceKey> instances) {
  CasterKey k;
  k.values = {light.directional ? 1.0f : 0.0f, light.position.x, light.position.y, light.position.z,
              light.direction.x, light.direction.y, light.direction.z, float(s.map_size), s.caster_shade,
              s.lod_bias, float(s.blur_passes), s.blur_offset, s.decimate ? 1.0f : 0.0f};
  for (const CasterInstanceKey& i : instances) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) k.values.push_back(i.transform[c][r]);
    k.values.push_back(i.shade);
    k.hashes.push_back(i.mesh_hash);
  }
  return k;
}

void ProjectiveCache::begin_frame() {
  rebuilt_ = reused_ = 0;
  for (auto& [id, e] : entries_) e.used = false;
}

void ProjectiveCache::end_frame() {
  std::erase_if(entries_, [](const auto& kv) { return !kv.second.used; });
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
