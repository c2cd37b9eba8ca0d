// The vertex stage's clip test, eight planes at once: one lane per plane of ClipPlanes (unused lanes always
// pass), so the per-vertex cost is four multiply-adds and a compare whatever planes a draw has.
#pragma once
#include <glm/vec4.hpp>

#include "raster/clip.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

class OutcodeTester {
 public:
  explicit OutcodeTester(const ClipPlanes& cp) : count_(cp.count) {
    alignas(32) float nx[8], ny[8], nz[8], nw[8], b[8];
    for (int k = 0; k < 8; ++k) {
      const bool used = k < cp.count;
      nx[k] = used ? cp.planes[k].n.x : 0.0f;
      ny[k] = used ? cp.planes[k].n.y : 0.0f;
      nz[k] = used ? cp.planes[k].n.z : 0.0f;
      nw[k] = used ? cp.planes[k].n.w : 0.0f;
      b[k] = used ? cp.planes[k].bias : 1.0f;
    }
    nx_ = simd::VecF32::load(nx), ny_ = simd::VecF32::load(ny), nz_ = simd::VecF32::load(nz);
    nw_ = simd::VecF32::load(nw), bias_ = simd::VecF32::load(b);
  }

  // Bit k: outside plane k (NaN counts as outside); bit `count`: w not strictly positive — such a vertex can lie
  // inside every plane only at the eye (x = y = z = w = 0 when not clamping), and the clipper rejects any
  // polygon keeping one (llvmpipe would divide by zero there).
  unsigned operator()(const glm::vec4& v) const {
    using simd::VecF32;
    // Same operation order as plane_distance(): ((nx·x + ny·y) + nz·z) + nw·w + bias, separately rounded.
    const VecF32 d = nx_ * VecF32::splat(v.x) + ny_ * VecF32::splat(v.y) + nz_ * VecF32::splat(v.z) +
                     nw_ * VecF32::splat(v.w) + bias_;
    const unsigned inside = simd::cmp_le(VecF32::splat(0.0f), d).bits();
    unsigned code = ~inside & ((1u << count_) - 1u);
    if (!(v.w > 0.0f)) code |= 1u << count_;
    return code;
  }

 private:
  int count_;
  simd::VecF32 nx_, ny_, nz_, nw_, bias_;
};

SHADOWLAB_ISA_END
}  // namespace raster
