// The exact reference's geometry: an Intel Embree BVH over world-space triangles (the casters the frame's shadow
// passes rasterised) answering occlusion rays. Triangles are two-sided: a ray is blocked by either face, as a
// shadow map built from front and back faces is. Embree may use its own threads to build; queries are const and
// safe from any thread, and their answer depends only on the ray and the triangles, not on the BVH's shape.
// Alpha-masked casters are a geometry of their own with an occlusion filter that rejects a hit where the
// material's alpha (level 0 of its texture at the hit's texture coordinates) is below the cutoff, the alpha test
// the depth passes run (shading/surface_texture.h).
#pragma once
#include <memory>
#include <span>
#include <stdexcept>

#include <glm/vec3.hpp>

#include "scenes/scene_queries.h"
#include "shading/surface_texture.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

// Embree refused to create a device or build the scene; what() says which and why.
struct ReferenceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OcclusionScene {
 public:
  explicit OcclusionScene(const scenes::TriangleSoup& triangles);
  // The opaque soup as above, and each masked material's triangles tested against surfaces[material]; the
  // surfaces (and their textures) must outlive the scene.
  OcclusionScene(const scenes::CoverageSoup& casters, std::span<const shading::SurfaceTexture> surfaces);
  ~OcclusionScene();
  OcclusionScene(const OcclusionScene&) = delete;
  OcclusionScene& operator=(const OcclusionScene&) = delete;

  // Whether any triangle meets the segment origin + t · direction for t in [0, t_max] (t_max may be infinite).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float t_max) const;

  size_t triangles() const { return triangles_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  size_t triangles_ = 0;
};

SHADOWLAB_ISA_END
}  // namespace reference
