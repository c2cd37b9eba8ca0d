// The OpenGL tutorial's automatic light frustum for a directional light (seed 001, "Automatic light frustum"),
// object by object on bounding boxes: the potential shadow receivers (objects in the light frustum, the view
// frustum and the scene box, minus those beyond a cut-off) and their box; the potential shadow casters (those
// receivers plus every caster between that box and the light); and the final box, aligned with the light,
// around the casters. smooth_light_box is the tutorial's remedy for popping across the frames of a sequence.
// Used by the classic technique with fit = tutorial (classic.cpp); today's fit = auto is light_frustum.h's.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shading/techniques/light_frustum.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// What the sets are taken against besides the objects.
struct TutorialFitInput {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels
  glm::mat4 camera_view_proj{1.0f};
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit; view distance = dot(p − eye, forward)
  float cutoff = 100.0f;                 // receivers whose nearest view distance is beyond this are dropped
  Box scene;                             // the scene box
};

// The two sets, as ascending indices into the objects, and the receivers' world box. Every receiver is also
// in `casters` (the tutorial's PSCs include the PSRs).
struct TutorialSets {
  std::vector<size_t> receivers, casters;
  Box receiver_box;
};

// True when the box is not wholly outside one of the six clip planes of view_proj (GL clip space, −w ≤ x, y,
// z ≤ w): the usual conservative box-frustum test.
bool box_in_frustum(const glm::mat4& view_proj, const Box& b);
// The smallest view distance dot(p − eye, forward) over the box.
float nearest_view_distance(const Box& b, glm::vec3 eye, glm::vec3 forward);
// True when the boxes overlap (closed: touching counts).
bool boxes_overlap(const Box& a, const Box& b);
// The light's rotated frame as rows: x and y across the light (light_up's lookAt), z towards the light.
glm::mat3 light_rotation(glm::vec3 direction);
// The box of the eight corners of b in the frame `rotation`.
Box rotated_box(const glm::mat3& rotation, const Box& b);
// True when `object` lies between `receivers` and a directional light: in the light's frame their boxes overlap
// across the light, and some of the object is nearer the light than the receivers' farthest point.
bool between_box_and_light(const glm::mat3& rotation, const Box& object, const Box& receivers);

TutorialSets tutorial_sets(std::span<const ObjectBounds> objects, const TutorialFitInput& in);

// The final box in the light's frame around every caster of `sets` (the receivers included); with no receivers,
// around the scene box.
LightBox tutorial_light_box(std::span<const ObjectBounds> objects, const TutorialSets& sets,
                            const TutorialFitInput& in);

// Smoothing over time: a box that grew is taken at once (nothing in it may be cut off), a box that shrank is
// approached by 1 − smoothing of the difference per frame. `previous` is ignored when the light turned.
LightBox smooth_light_box(const LightBox& now, const std::optional<LightBox>& previous, float smoothing);

// The orthographic light of a box in the light's frame, widened by `margin` (relative) on every side.
LightMatrices light_box_matrices(const LightBox& b, float margin = 0.01f);

SHADOWLAB_ISA_END
}  // namespace shading::tech
