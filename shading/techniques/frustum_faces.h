// The face-split perspective maps of seed 003 (Ulrich, Blow and Schamel, 2003), built here as the seed
// describes: look at the view frustum from the light; every frustum face that faces the light (up to five) is
// extruded along the light direction, and gets a map whose projection exactly covers that face as the light
// sees it: the homography taking the face's quadrilateral to the map's square, which is a perspective
// projection (a "PSM frustum") with its centre of projection on the line through the eye. A point belongs to
// the face its ray towards the light leaves the frustum through (those faces tile the frustum as the light sees
// it); it reads that face's map. Option: the centre of projection moved back by LiSPSM's rule
// (n + √(n·f) instead of n), which keeps the face covered but spreads the resolution more evenly.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "shading/techniques/technique.h"
#include "shading/techniques/view_fit.h"
#include "shading/techniques/view_frustum.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

enum class FaceWarp : uint8_t { exact, lispsm };

struct FaceMap {
  std::string label;            // near, far, left, right, bottom, top
  FittedMap fit;                // light view, and the face's projection with depth
  glm::mat4 owner{1.0f};        // world → (s, t, 0, q): the face itself is s/q, t/q ∈ [0, 1] (no guard band)
};

struct FacePlan {
  std::vector<FaceMap> faces;   // the light-facing faces, at most five
};

// The maps of the frustum between view distances range.near and range.far for a light travelling along
// `direction`; each map extends `guard_texels` beyond its face so filters near a boundary read real depths.
FacePlan plan_face_maps(glm::vec3 direction, const CameraView& camera, ViewRange range, const Box& casters,
                        int map_size, FaceWarp warp, float guard_texels = 2.0f);

// The face point p belongs to: the one whose square it lies deepest inside (largest min(s, 1−s, t, 1−t), so a
// boundary point goes to one face, deterministically); `margin` receives that depth (< 0: outside every face).
size_t face_owner(const FacePlan& plan, glm::vec3 p, float* margin = nullptr);

// The registry's factory.
std::unique_ptr<LightShadow> plan_frustum_faces(const LightDesc& light, const ShadowConfig& config,
                                                const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
