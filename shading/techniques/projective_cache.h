// The per-caster map cache: a map is rebuilt only when its key changes: the light, the settings that shape the
// map, the caster's instances (transforms, greys) or their meshes (a content hash). Keys are compared exactly
// (every float, the hashes), so a change anywhere rebuilds and nothing else does. Lives across frames.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "shading/techniques/projective_map.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// One instance of a caster as the key sees it.
struct CasterInstanceKey {
  glm::mat4 transform{1.0f};
  float shade = 0.0f;
  uint64_t mesh_hash = 0;  // mesh_content_hash of its mesh
};

struct CasterKey {
  std::vector<float> values;     // light, settings, transforms, greys
  std::vector<uint64_t> hashes;  // mesh contents
  bool operator==(const CasterKey&) const = default;
};

// A 64-bit FNV-1a-style hash of the bytes of the positions and indices (eight bytes per step).
uint64_t mesh_content_hash(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

CasterKey make_caster_key(const ProjectiveLight& light, const ProjectiveSettings& settings,
                          std::span<const CasterInstanceKey> instances);

class ProjectiveCache {
 public:
  // Starts a frame: the counters restart and every entry is marked unused.
  void begin_frame();
  // The map of caster `id` (any number unique per light and caster) for `key`: the cached one when the key
  // is unchanged, else the result of build(), which replaces it.
  template <class Build>
  std::shared_ptr<const CasterMap> get(uint64_t id, const CasterKey& key, Build&& build) {
    Entry& e = entries_[id];
    e.used = true;
    if (e.map && e.key == key) {
      ++reused_;
      return e.map;
    }
    e.key = key;
    e.map = std::make_shared<const CasterMap>(build());
    ++rebuilt_;
    return e.map;
  }
  // Keeps the map of caster `id` (if any) through end_frame without asking for it: a caster skipped this frame
  // keeps its map for when it is needed again (its key is still checked then).
  void keep(uint64_t id) {
    if (auto it = entries_.find(id); it != entries_.end()) it->second.used = true;
  }
  // Ends a frame: entries not asked for this frame are dropped.
  void end_frame();

  size_t rebuilt() const { return rebuilt_; }  // this frame
  size_t reused() const { return reused_; }
  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    CasterKey key;
    std::shared_ptr<const CasterMap> map;
    bool used = false;
  };
  std::map<uint64_t, Entry> entries_;
  size_t rebuilt_ = 0, reused_ = 0;
};

SHADOWLAB_ISA_END
}  // namespace shading::tech
