// Geometry queries the renderer needs from a built scene: exact world-space bounds of instances, objects and
// the whole scene, triangle counts, and the scene flattened into world-space triangle soup for depth passes.
#pragma once
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace scenes {

// An axis-aligned box; empty when nothing was added (min > max).
struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    if (!b.empty()) extend(b.min), extend(b.max);
  }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
  bool operator==(const Aabb&) const = default;
};

// Which instances a query looks at.
enum class InstanceFilter : uint8_t { all, casters, receivers };

bool passes(const Instance& instance, InstanceFilter filter);

// Model-space bounds of every vertex of a mesh.
Aabb mesh_bounds(const Mesh& mesh);
// Exact world-space bounds: every vertex of the instance's mesh transformed.
Aabb instance_bounds(const Scene& scene, size_t instance);
// Bounds of every instance of a top-level object (Instance::object).
Aabb object_bounds(const Scene& scene, uint32_t object);
Aabb scene_bounds(const Scene& scene, InstanceFilter filter = InstanceFilter::all);

// The instances of a top-level object, in scene order.
std::vector<uint32_t> object_instances(const Scene& scene, uint32_t object);

// Triangles drawn, every instance counted.
size_t triangle_count(const Scene& scene, InstanceFilter filter = InstanceFilter::all);

// World-space triangles: positions transformed by each instance's matrix, indices into `positions`,
// counter-clockwise front faces (mirrored instances are already flipped in a built scene).
struct TriangleSoup {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  size_t triangle_count() const { return indices.size() / 3; }
};
TriangleSoup flatten(const Scene& scene, InstanceFilter filter = InstanceFilter::all);

// What a material's alpha does to its surface (Material::alpha_mode): nothing (opaque), a per-fragment alpha
// test against its texture (masked), or every fragment discarded (hidden: no texture and a factor alpha below
// the cutoff). A mask with no texture is opaque or hidden as a whole.
enum class Coverage : uint8_t { opaque, masked, hidden };
Coverage coverage(const Material& material);
// The cutoff a fragment's alpha is compared with: alpha_cutoff for mask, 0.5 for blend (scene.h); 0 for opaque.
float alpha_cutoff(const Material& material);

// World-space triangles of the masked instances of one material, with their texture coordinates.
struct MaskedSoup {
  uint32_t material = 0;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> texcoords;  // one per position; (0, 0) where the mesh has none
  std::vector<uint32_t> indices;
};
// The instances a depth pass draws, split by coverage: the opaque ones in one soup (the depth-only path), the
// masked ones per material in instance order (a pass with the alpha test), the hidden ones left out.
struct CoverageSoup {
  TriangleSoup opaque;
  std::vector<MaskedSoup> masked;
};
CoverageSoup flatten_by_coverage(const Scene& scene, InstanceFilter filter);
TriangleSoup flatten_instances(const Scene& scene, std::span<const uint32_t> instances);

}  // namespace scenes
