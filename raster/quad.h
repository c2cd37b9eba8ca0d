// The 2×2 quad a fragment shader runs on, and the derivatives it allows. Lanes are ordered
// 0 = (x, y), 1 = (x+1, y), 2 = (x, y+1), 3 = (x+1, y+1) in window pixels (y up), with (x, y) even.
// Lanes not covered by the triangle are helper lanes: they are shaded so derivatives exist, never written.
#pragma once
#include <array>
#include <cstdint>

#include <glm/vec4.hpp>

namespace raster {

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

}  // namespace raster
