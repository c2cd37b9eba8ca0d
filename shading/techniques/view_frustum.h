// The camera's view frustum as the view-following techniques cut it: the part of it where receivers can be
// (a range of view distances), slices of that range by the practical split scheme, and the world-space corners
// of any slice. Cascades, LiSPSM and the frustum-face maps are all fitted to what these functions return.
#pragma once
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/techniques/light_frustum.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// A range of view distances along the camera's forward axis.
struct ViewRange {
  float near = 0.1f, far = 100.0f;
};

// The view distance of world point p: dot(p − eye, forward).
float view_distance(const CameraView& c, glm::vec3 p);

// The camera's [near, far] clipped to the view distances of the frustum's part inside the receivers' box (the
// body of LiSPSM and of the 2003 face maps: frustum ∩ scene box), widened by a thousandth of its length: no
// slice covers space beyond the last receiver the camera can see or before the first. A box corner outside the
// frustum, behind or beside the camera, does not pull the near distance in (with a perspective warp, a near
// distance too small spends most of the map in front of every receiver). The box's corners where it does not
// meet the frustum; the camera's range when the box is empty.
ViewRange receiver_view_range(const CameraView& c, const Box& receivers);

// The visible samples' range, widened by a hundredth of its length each way and kept inside [near, far].
ViewRange visible_view_range(const CameraView& c, const VisibleSamples& v);

// The m + 1 split distances C_0 = n .. C_m = f of the practical scheme:
// C_i = λ·n·(f/n)^(i/m) + (1 − λ)·(n + (f − n)·i/m); λ = 1 logarithmic, λ = 0 uniform.
std::vector<float> practical_splits(float n, float f, int m, float lambda);

// The world-space corners of the frustum between view distances a and b: [0..3] at a, [4..7] at b, each
// quadruple in the order (−x, −y), (+x, −y), (+x, +y), (−x, +y) of the camera's view space.
std::array<glm::vec3, 8> slice_corners(const CameraView& c, float a, float b);

// Points whose bounds (and any linear-fractional bound, e.g. a LiSPSM crop) hold every visible point at view
// distances [a, b]: for each visible tile overlapping [a, b], the corners of its rectangle at the overlap's two
// distances. Appended to `out`.
void visible_body(const CameraView& c, const VisibleSamples& v, float a, float b, std::vector<glm::vec3>& out);

// The vertices of the convex intersection of a frustum slice (slice_corners order) and a box: the corners of
// each inside the other and the crossings of each one's edges with the other's faces. Any linear or
// linear-fractional bound of the intersection (a crop in light space) is reached at one of them. Empty when the
// two do not overlap.
std::vector<glm::vec3> clip_slice_to_box(const std::array<glm::vec3, 8>& slice, const Box& box);

SHADOWLAB_ISA_END
}  // namespace shading::tech
