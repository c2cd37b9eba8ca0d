// The 2×2 quad a fragment shader runs on, and the derivatives it allows. Lanes are ordered
// 0 = (x, y), 1 = (x+1, y), 2 = (x, y+1), 3 = (x+1, y+1) in window pixels (y up), with (x, y) even.
// Lanes not covered by the triangle are helper lanes: they are shaded so derivatives exist, never written.
// The wide form, QuadPairIn / QuadPairOut, holds two quads side by side (4×2 pixels) in SIMD lanes.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <glm/vec4.hpp>

#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Number of floats in a shader's Varyings (0 for an empty struct).
template <class V>
inline constexpr int kVaryingFloats = std::is_empty_v<V> ? 0 : int(sizeof(V) / sizeof(float));

template <class Varyings>
struct QuadIn {
  std::array<Varyings, 4> in;            // interpolated at each lane's pixel centre
  std::array<glm::vec4, 4> frag_coord;   // gl_FragCoord: window x, y (pixel centre), window z, 1/w_clip
  uint8_t live = 0;                      // bit l set: lane l is covered (not a helper lane)
  bool front_facing = true;
};

struct QuadOut {
  std::array<glm::vec4, 4> color{};
  std::array<float, 4> depth{};  // read only when the shader declares kWritesDepth
  uint8_t discard = 0;           // bit l set: lane l is discarded (only when the shader declares kDiscards)
};

// Fine derivatives: each row (dFdx) or column (dFdy) of the quad uses its own difference.
template <class T>
std::array<T, 4> dfdx_fine(const std::array<T, 4>& v) {
  return {v[1] - v[0], v[1] - v[0], v[3] - v[2], v[3] - v[2]};
}
template <class T>
std::array<T, 4> dfdy_fine(const std::array<T, 4>& v) {
  return {v[2] - v[0], v[3] - v[1], v[2] - v[0], v[3] - v[1]};
}
// Coarse derivatives: one difference for the whole quad, from the lower row / left column.
template <class T>
std::array<T, 4> dfdx_coarse(const std::array<T, 4>& v) {
  const T d = v[1] - v[0];
  return {d, d, d, d};
}
template <class T>
std::array<T, 4> dfdy_coarse(const std::array<T, 4>& v) {
  const T d = v[2] - v[0];
  return {d, d, d, d};
}

// ---- Two quads side by side: the 4×2 pixel group of the wide fragment stage, one pixel per SIMD lane.
// Lane i is pixel (x + (i & 3), y + (i >> 2)) with (x, y) even: lanes 0–3 the lower row, 4–7 the upper row.
// Quad 0 is lanes {0, 1, 4, 5}, quad 1 lanes {2, 3, 6, 7}, each with the roles of QuadIn's lanes 0..3. A quad
// with no covered pixel beside one that has some is shaded too, all helper lanes, and never written.
template <class Varyings>
struct QuadPairIn {
  // The floats of Varyings in declaration order (in[varying_index(&V::uv)] is uv.x, the next one uv.y, …),
  // each interpolated at the eight pixel centres exactly as QuadIn's are.
  std::array<simd::VecF32, size_t(kVaryingFloats<Varyings>)> in;
  simd::VecF32 frag_x, frag_y, frag_z, frag_w;  // gl_FragCoord per lane, as QuadIn::frag_coord
  uint8_t live = 0;                             // bit i set: lane i is covered (not a helper lane)
  bool front_facing = true;
};

struct QuadPairOut {
  std::array<simd::VecF32, 4> color;  // r, g, b, a per lane
  simd::VecF32 depth;                 // read only when the shader declares kWritesDepth
  uint8_t discard = 0;                // bit i set: lane i is discarded (only when the shader declares kDiscards)
};

// Index in QuadPairIn::in of the first float of a member of Varyings.
template <class V, class T>
int varying_index(T V::*member) {
  const V v{};
  return int((reinterpret_cast<const std::byte*>(&(v.*member)) - reinterpret_cast<const std::byte*>(&v)) /
             ptrdiff_t(sizeof(float)));
}

// Derivatives over the pair, the same differences as the quad functions above, lane by lane.
namespace pair_detail {
inline simd::VecF32 diff(simd::VecF32 v, simd::VecI32 to, simd::VecI32 from) {
  return simd::permute(v, to) - simd::permute(v, from);
}
inline simd::VecI32 lanes(int a, int b, int c, int d) {
  alignas(32) const int32_t i[8] = {a, a, b, b, c, c, d, d};
  return simd::VecI32::load(i);
}
}  // namespace pair_detail
inline simd::VecF32 dfdx_fine(simd::VecF32 v) {
  return pair_detail::diff(v, pair_detail::lanes(1, 3, 5, 7), pair_detail::lanes(0, 2, 4, 6));
}
inline simd::VecF32 dfdy_fine(simd::VecF32 v) {
  alignas(32) const int32_t up[8] = {4, 5, 6, 7, 4, 5, 6, 7}, down[8] = {0, 1, 2, 3, 0, 1, 2, 3};
  return pair_detail::diff(v, simd::VecI32::load(up), simd::VecI32::load(down));
}
inline simd::VecF32 dfdx_coarse(simd::VecF32 v) {
  return pair_detail::diff(v, pair_detail::lanes(1, 3, 1, 3), pair_detail::lanes(0, 2, 0, 2));
}
inline simd::VecF32 dfdy_coarse(simd::VecF32 v) {
  return pair_detail::diff(v, pair_detail::lanes(4, 6, 4, 6), pair_detail::lanes(0, 2, 0, 2));
}

SHADOWLAB_ISA_END
}  // namespace raster
