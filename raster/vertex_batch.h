// The vertex stage's fixed-function part eight vertices at a time: the clip test (outcodes, as OutcodeTester)
// and, for vertices inside every plane, the viewport transform and snapping (as to_window() in setup.h), one
// vertex per SIMD lane with the very same float operations in the same order, so the results are bit for bit
// those of the one-vertex code. Front end of the pipeline, after the vertex shader.
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>

#include "raster/clip.h"
#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/setup.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

class VertexBatch {
 public:
  // `invalid` is the code of a vertex with a coordinate that is not finite.
  VertexBatch(const ClipPlanes& cp, const SetupParams& sp, unsigned invalid)
      : planes_(cp), sp_(sp), invalid_(invalid), frustum_(is_frustum(cp)) {}

  // Lanes [0, n) of the clip-space positions (x, y, z, w), n <= 8: codes[l] for each, and win[l] for those
  // whose code is 0 (the others' win[l] is left alone; when all eight are inside, win[0..7] are written at once).
  void run(simd::VecF32 px, simd::VecF32 py, simd::VecF32 pz, simd::VecF32 pw, int n, unsigned* codes,
           WindowVertex* win) const {
    using simd::Mask;
    using simd::VecF32;
    using simd::VecI32;
    // std::isfinite: the exponent field is not all ones.
    const VecI32 exp = VecI32::splat(0x7f800000);
    auto finite = [&](VecF32 v) { return simd::cmp_neq(simd::bitcast_i32(v) & exp, exp); };
    const Mask ok = finite(px) & finite(py) & finite(pz) & finite(pw);
    // Outcodes: bit k when outside plane k, ((nx·x + ny·y) + nz·z) + nw·w + bias < 0 or NaN (OutcodeTester).
    VecI32 code = VecI32::splat(0);
    const VecF32 zero = VecF32::splat(0.0f);
    auto outside = [&](VecF32 d, int k) {
      code = code | simd::select(simd::cmp_le(zero, d), VecI32::splat(1 << k), VecI32::splat(0));
    };
    if (frustum_) {
      // The frustum's planes (make_clip_planes): their distances are exactly w − x, x + w, w − y, y + w, z + w and
      // w − z for finite coordinates (clip.h, plane_distance), and a vertex with any other is invalid below.
      outside(pw - px, 0), outside(px + pw, 1), outside(pw - py, 2), outside(py + pw, 3);
      if (planes_.count == 6) outside(pz + pw, 4), outside(pw - pz, 5);
    } else {
      for (int k = 0; k < planes_.count; ++k) {
        const ClipPlane& p = planes_.planes[size_t(k)];
        outside(VecF32::splat(p.n.x) * px + VecF32::splat(p.n.y) * py + VecF32::splat(p.n.z) * pz +
                    VecF32::splat(p.n.w) * pw + VecF32::splat(p.bias),
                k);
      }
    }
    code = code | simd::select(simd::cmp_lt(zero, pw), VecI32::splat(1 << planes_.count), VecI32::splat(0));
    code = simd::select(ok, VecI32::splat(int32_t(invalid_)), code);
    alignas(32) uint32_t c[8];
    code.store_u32(c);
    unsigned inside = 0;
    for (int l = 0; l < n; ++l) {
      codes[l] = c[l];
      inside |= unsigned(c[l] == 0) << l;
    }
    if (inside == 0) return;
    // to_window(): ndc = clip · (1/w), then one fused multiply-add per axis, snapping by round-to-nearest-even.
    const VecF32 inv_w = simd::div(VecF32::splat(1.0f), pw);
    const VecF32 nx = px * inv_w, ny = py * inv_w, nz = pz * inv_w;
    const VecF32 wx = simd::fma(nx, VecF32::splat(sp_.vp_half_w), VecF32::splat(sp_.vp_center_x));
    const VecF32 wy = simd::fma(ny, VecF32::splat(sp_.vp_half_h), VecF32::splat(sp_.vp_center_y));
    const VecF32 wz = simd::fma(nz, VecF32::splat(0.5f), VecF32::splat(0.5f));
    const VecI32 sx = simd::round_to_int(wx * VecF32::splat(float(kSubpixelScale)));
    const VecI32 sy = simd::round_to_int(wy * VecF32::splat(float(kSubpixelScale)));
    if (inside == 0xFFu) {  // all eight: one transposing store of the eight consecutive records
      static_assert(sizeof(WindowVertex) == 6 * sizeof(float) && offsetof(WindowVertex, sy) == 5 * sizeof(float));
      simd::store_interleaved6(win, wx, wy, wz, inv_w, simd::bitcast_f32(sx), simd::bitcast_f32(sy));
      return;
    }
    alignas(32) float out[4][8];
    alignas(32) uint32_t snapped[2][8];
    wx.store(out[0]), wy.store(out[1]), wz.store(out[2]), inv_w.store(out[3]);
    sx.store_u32(snapped[0]), sy.store_u32(snapped[1]);
    for (unsigned m = inside; m != 0; m &= m - 1) {
      const int l = std::countr_zero(m);
      win[l] = WindowVertex{out[0][l], out[1][l], out[2][l], out[3][l], int32_t(snapped[0][l]), int32_t(snapped[1][l])};
    }
  }

  // Whether cp holds make_clip_planes()'s planes, in its order: x <= w, x >= −w, y <= w, y >= −w, then with six
  // planes z >= −w, z <= w. Such planes take the direct distances in run().
  static bool is_frustum(const ClipPlanes& cp) {
    static constexpr float kNormals[6][4] = {{-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1},
                                             {0, 1, 0, 1},  {0, 0, 1, 1}, {0, 0, -1, 1}};
    if (cp.count != 4 && cp.count != 6) return false;
    for (int k = 0; k < cp.count; ++k) {
      const ClipPlane& p = cp.planes[size_t(k)];
      if (p.n != glm::vec4(kNormals[k][0], kNormals[k][1], kNormals[k][2], kNormals[k][3]) || p.bias != 0.0f)
        return false;
    }
    return true;
  }

 private:
  ClipPlanes planes_;
  SetupParams sp_;
  unsigned invalid_;
  bool frustum_;  // is_frustum(planes_): the clip test takes the planes' exact distances
};

SHADOWLAB_ISA_END
}  // namespace raster
