// Cube map addressing: GL's major-axis table (GL 4.6 table 8.19) that turns a direction into a face and face
// coordinates (s, t), the face derivatives that give a cube lookup its LOD, where a texel just off one face
// continues on the next (seamless filtering), and the view matrix that renders a face so that it reads back
// through that same table.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// GL's face order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face).
enum class CubeFace : uint8_t { pos_x, neg_x, pos_y, neg_y, pos_z, neg_z };

// Per face: the major axis (pointing out through the face) and the axes along which s and t grow. From GL's
// table: sc, tc, ma for +X: −rz, −ry, rx; −X: +rz, −ry, rx; +Y: +rx, +rz, ry; −Y: +rx, −rz, ry;
// +Z: +rx, −ry, rz; −Z: −rx, −ry, rz; then s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
struct CubeFaceAxes {
  glm::ivec3 major, s_axis, t_axis;
};
inline constexpr CubeFaceAxes kCubeFaceAxes[6] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

inline float dot_axis(glm::vec3 d, glm::ivec3 a) {
  // Axes are unit vectors along x, y or z: pick the component and its sign (no rounding).
  return a.x != 0 ? (a.x > 0 ? d.x : -d.x) : a.y != 0 ? (a.y > 0 ? d.y : -d.y) : (a.z > 0 ? d.z : -d.z);
}

// The face a direction selects. GL leaves ties to the implementation; like llvmpipe (and Direct3D) this prefers
// z over y over x: z when |z| >= max(|x|, |y|), else x when |x| > |y|, else y. The sign bit picks positive or
// negative (so −0 selects the negative face, as llvmpipe's sign-bit test does).
inline int cube_face_of(glm::vec3 d) {
  const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  if (az >= std::fmax(ax, ay)) return std::signbit(d.z) ? 5 : 4;
  if (ax > ay) return std::signbit(d.x) ? 1 : 0;
  return std::signbit(d.y) ? 3 : 2;
}

struct CubeCoord {
  int face = 0;
  float s = 0.5f, t = 0.5f;      // face coordinates in [0, 1]
  float sc = 0, tc = 0, ma = 0;  // GL's sc, tc and |ma|
};

// Face and face coordinates of a direction. s = sc · (0.5 / |ma|) + 0.5 as llvmpipe evaluates it; a zero
// direction gives the face centre.
inline CubeCoord cube_coord(glm::vec3 d) {
  CubeCoord c;
  c.face = cube_face_of(d);
  const CubeFaceAxes& a = kCubeFaceAxes[c.face];
  c.sc = dot_axis(d, a.s_axis);
  c.tc = dot_axis(d, a.t_axis);
  c.ma = dot_axis(d, a.major);
  const float half_inv = c.ma > 0.0f ? 0.5f / c.ma : 0.0f;
  c.s = c.sc * half_inv + 0.5f;
  c.t = c.tc * half_inv + 0.5f;
  return c;
}

// Derivatives of (s, t) on the selected face for a derivative `dd` of the direction (quotient rule on
// s = (sc / ma + 1) / 2): ds = (dsc − sc · dma / ma) / (2 ma).
inline glm::vec2 cube_face_derivative(const CubeCoord& c, glm::vec3 dd) {
  if (!(c.ma > 0.0f)) return {0.0f, 0.0f};
  const CubeFaceAxes& a = kCubeFaceAxes[c.face];
  const float dsc = dot_axis(dd, a.s_axis), dtc = dot_axis(dd, a.t_axis), dma = dot_axis(dd, a.major);
  const float k = 0.5f / c.ma;
  return {(dsc - c.sc * dma / c.ma) * k, (dtc - c.tc * dma / c.ma) * k};
}

// A texel of a face, by index.
struct FaceTexel {
  int face, i, j;
};

// Where texel (i, j) of `face` continues when exactly one of i, j lies one step outside [0, n): the adjacent
// face's texel that touches the same edge at the same place along it. Computed exactly in integers: the centre
// of (i, j) is the direction n·major + (2i + 1 − n)·s_axis + (2j + 1 − n)·t_axis (scaled by n), whose
// off-face component now dominates; that direction is looked up like any other and floored to a texel.
inline FaceTexel cube_neighbor(int face, int i, int j, int n) {
  const CubeFaceAxes& a = kCubeFaceAxes[face];
  const glm::ivec3 d = n * a.major + (2 * i + 1 - n) * a.s_axis + (2 * j + 1 - n) * a.t_axis;
  const int ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  const int f = az > ax && az > ay ? (d.z < 0 ? 5 : 4) : ax > ay ? (d.x < 0 ? 1 : 0) : (d.y < 0 ? 3 : 2);
  const CubeFaceAxes& b = kCubeFaceAxes[f];
  auto dot = [](glm::ivec3 u, glm::ivec3 v) { return int64_t(u.x) * v.x + int64_t(u.y) * v.y + int64_t(u.z) * v.z; };
  const int64_t ma = dot(d, b.major), sc = dot(d, b.s_axis), tc = dot(d, b.t_axis);
  // floor(n · (sc / ma + 1) / 2) with sc + ma >= 0: an exact integer division.
  auto texel = [&](int64_t c) {
    const int64_t k = (int64_t(n) * (c + ma)) / (2 * ma);
    return int(k < 0 ? 0 : (k >= n ? n - 1 : k));
  };
  return {f, texel(sc), texel(tc)};
}

// The view matrix that renders face `face` of a cube map seen from `eye`: looking along the face's major axis
// with up = its t axis, so that with glm::perspective(90°, 1, near, far) and a viewport covering the face,
// window (x, y) / size is exactly the (s, t) that cube_coord gives for the same direction (window row 0 is
// t = 0). These are the usual up vectors (−Y for the four side faces, +Z for +Y, −Z for −Y).
inline glm::mat4 cube_face_view(int face, glm::vec3 eye) {
  const CubeFaceAxes& a = kCubeFaceAxes[face];
  return glm::lookAt(eye, eye + glm::vec3(a.major), glm::vec3(a.t_axis));
}

SHADOWLAB_ISA_END
}  // namespace shading
