// Triangle setup (see setup.h): viewport transform, snapping, culling, integer edges with the tie rule,
// bounding box and depth plane. Integer ranges are derived in limits.h.
#include "raster/setup.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "raster/limits.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

SetupParams make_setup_params(const DrawState& s, int tw, int th, DepthFormat format) {
  // GL's viewport limits (glViewport clamps; llvmpipe: GL_MAX_VIEWPORT_DIMS 16384, bounds [-32768, 32767]),
  // which also bound window coordinates (limits.h).
  Rect vp = s.viewport.value_or(Rect{0, 0, tw, th});
  vp.width = std::clamp(vp.width, 1, kMaxTargetSize);
  vp.height = std::clamp(vp.height, 1, kMaxTargetSize);
  vp.x = std::clamp(vp.x, kViewportMin, kViewportMax);
  vp.y = std::clamp(vp.y, kViewportMin, kViewportMax);
  SetupParams p{};
  p.vp_half_w = float(vp.width) * 0.5f;
  p.vp_center_x = float(vp.x) + float(vp.width) * 0.5f;
  p.vp_half_h = float(vp.height) * 0.5f;
  p.vp_center_y = float(vp.y) + float(vp.height) * 0.5f;
  PixelRect r{std::max(0, vp.x), std::max(0, vp.y), std::min(tw, vp.x + vp.width) - 1,
              std::min(th, vp.y + vp.height) - 1};
  if (s.scissor) {
    r.x0 = std::max(r.x0, s.scissor->x);
    r.y0 = std::max(r.y0, s.scissor->y);
    r.x1 = std::min(r.x1, s.scissor->x + s.scissor->width - 1);
    r.y1 = std::min(r.y1, s.scissor->y + s.scissor->height - 1);
  }
  p.clip = r;
  p.cull = s.cull;
  p.front_face = s.front_face;
  p.offset = s.polygon_offset;
  p.format = format;
  p.depth_clamp = s.depth_clamp;
  return p;
}

float polygon_offset_r(DepthFormat format, float max_depth) {
  switch (format) {
    case DepthFormat::d16: return float(2.0 / 65535.0);
    case DepthFormat::d24: return float(2.0 / 16777215.0);
    case DepthFormat::d32f: {
      // llvmpipe's bit arithmetic: exponent field of |max_depth| minus 23, clamped at zero (then the float is 0).
      const int32_t bits = int32_t(std::bit_cast<uint32_t>(std::fabs(max_depth)) & 0x7f800000u) - (23 << 23);
      return std::bit_cast<float>(uint32_t(std::max(bits, 0)));
    }
  }
  return 0.0f;
}

namespace {

// Tie rule (CONVENTIONS): a pixel centre exactly on an edge belongs to the triangle when the edge is a left
// edge (interior to its right, A > 0) or a horizontal edge with the interior above it (A == 0, B > 0).
// For a counter-clockwise triangle, edge a→b has inward normal (A, B) = (Y_a − Y_b, X_b − X_a).
void setup_edge(int32_t xa, int32_t ya, int32_t xb, int32_t yb, int k, TriangleSetup& out) {
  const int32_t A = ya - yb;
  const int32_t B = xb - xa;
  const bool inclusive = A > 0 || (A == 0 && B > 0);
  // E(i, j) = A·(256 i + 128 − X_a) + B·(256 j + 128 − Y_a) = 256 (A i + B j) + C.
  const int64_t C = int64_t(A) * (kSubpixelScale / 2 - xa) + int64_t(B) * (kSubpixelScale / 2 - ya);
  const int64_t bias = inclusive ? 0 : 1;
  // Inside: E − bias >= 0  ⇔  A i + B j >= ceil((bias − C) / 256); >> floors for negative values too.
  out.a[k] = A;
  out.b[k] = B;
  out.t[k] = (bias - C + (kSubpixelScale - 1)) >> kSubpixelBits;
}

// The depth plane exactly as Mesa 22.3's llvmpipe computes it (measured bit-exact on d32f against llvmpipe over
// ~10^6 pixels, with and without polygon offset):
//  * Triangle setup (lp_setup_tri.c, triangle_both/triangle_ccw/triangle_cw) hands its JIT setup function the
//    vertices as submitted when llvmpipe's fixed-point area is positive, i.e. when the triangle is clockwise in
//    our y-up window space, and as (v1, v0, v2) otherwise (rotate_fixed_position_01: provoking vertex last).
//  * The setup function (lp_state_setup.c: init_args, calc_coef4, lp_do_offset_tri) works in float, each
//    operation rounded on its own (no contraction), from the unsnapped window positions:
//      dx01 = x0 − x1, dy01 = y0 − y1, dx20 = x2 − x0, dy20 = y2 − y0, ooa = 1 / (dx01·dy20 − dy01·dx20)
//      dadx = (z0 − z1)·(dy20·ooa) − (z2 − z0)·(dy01·ooa)
//      dady = (z2 − z0)·(dx01·ooa) − (z0 − z1)·(dx20·ooa)
//      a0   = z0 − (dadx·(x0 − 0.5) + dady·(y0 − 0.5))          (the plane's value at pixel (0, 0)'s centre)
//  * The fragment shader (lp_bld_interp.c, attribs_update_simple) evaluates z at pixel (x, y) as
//    fma(dady, y, fma(dadx, x, a0)) (llvm.fmuladd, fused on FMA hardware) and then adds the polygon offset
//    with a separate float addition; the depth test clamps to [0, 1] and converts (lp_bld_depth.c,
//    lp_build_clamped_float_to_unsigned_norm): d24 = round_even(z · 16777215.0f); d16 = the low 16 bits of
//    z·(65535/65536) + 128, which equals round_even(z · 65535.0f) (scaling by 2^16 commutes with rounding).
//  * Polygon offset (lp_do_offset_tri) uses its own slopes, |(z20·y01 − y20·z01)·ooa| and
//    |(x20·z01 − z20·x01)·ooa|, o = max·factor + r·units with r = float(units · mrd · 2) for unorm formats
//    (lp_make_setup_variant_key: mrd = 1/65535 or 1/16777215, in double) and, for d32f, r = the float whose
//    exponent field is that of max(|z0|, |z1|, |z2|) minus 23 (zero if that underflows), times units.
void depth_plane(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, const SetupParams& p,
                 TriangleSetup& out) {
  const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y;
  const float dx20 = v2.x - v0.x, dy20 = v2.y - v0.y;
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  const float dx20o = dx20 * ooa, dy20o = dy20 * ooa, dx01o = dx01 * ooa, dy01o = dy01 * ooa;
  const float dz01 = v0.z - v1.z, dz20 = v2.z - v0.z;
  const float dzdx = dz01 * dy20o - dz20 * dy01o;
  const float dzdy = dz20 * dx01o - dz01 * dx20o;
  const float x0c = v0.x - 0.5f, y0c = v0.y - 0.5f;
  out.z_a0 = v0.z - (dzdx * x0c + dzdy * y0c);
  out.dzdx = dzdx;
  out.dzdy = dzdy;
  out.z_offset = 0.0f;
  if (p.offset.factor != 0.0f || p.offset.units != 0.0f) {
    const float ox = std::fabs((dz20 * dy01 - dy20 * dz01) * ooa);
    const float oy = std::fabs((dx20 * dz01 - dz20 * dx01) * ooa);
    const float m = (ox > oy || std::isnan(ox)) ? ox : oy;  // LLVMRealUGT select
    const float mult = m * p.offset.factor;
    float units;
    if (p.format == DepthFormat::d32f) {
      const float zmax = std::max(std::fabs(v2.z), std::max(std::fabs(v0.z), std::fabs(v1.z)));
      units = polygon_offset_r(p.format, zmax) * p.offset.units;
    } else {
      const double mrd = 1.0 / double(depth_max_code(p.format));
      units = float(double(p.offset.units) * mrd * 2.0);  // one rounding, from double
    }
    out.z_offset = units + mult;
  }
}

}  // namespace

SetupResult setup_triangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2,
                           const SetupParams& p, TriangleSetup& out) {
  const int64_t area2 = int64_t(v1.sx - v0.sx) * (v2.sy - v0.sy) - int64_t(v2.sx - v0.sx) * (v1.sy - v0.sy);
  if (area2 == 0) return SetupResult::degenerate;
  const bool ccw = area2 > 0;
  const bool front = (p.front_face == FrontFace::ccw) == ccw;
  if ((p.cull == CullMode::back && !front) || (p.cull == CullMode::front && front)) return SetupResult::culled;

  // Pixel bounding box: centres 256 i + 128 within [min, max] of the snapped coordinates.
  const int32_t xmin = std::min({v0.sx, v1.sx, v2.sx}), xmax = std::max({v0.sx, v1.sx, v2.sx});
  const int32_t ymin = std::min({v0.sy, v1.sy, v2.sy}), ymax = std::max({v0.sy, v1.sy, v2.sy});
  constexpr int32_t half = kSubpixelScale / 2;
  out.min_x = std::max(p.clip.x0, (xmin - half + kSubpixelScale - 1) >> kSubpixelBits);
  out.max_x = std::min(p.clip.x1, (xmax - half) >> kSubpixelBits);
  out.min_y = std::max(p.clip.y0, (ymin - half + kSubpixelScale - 1) >> kSubpixelBits);
  out.max_y = std::min(p.clip.y1, (ymax - half) >> kSubpixelBits);
  if (out.min_x > out.max_x || out.min_y > out.max_y) return SetupResult::outside;

  // Edges of the counter-clockwise ordering.
  const WindowVertex& a = v0;
  const WindowVertex& b = ccw ? v1 : v2;
  const WindowVertex& c = ccw ? v2 : v1;
  setup_edge(a.sx, a.sy, b.sx, b.sy, 0, out);
  setup_edge(b.sx, b.sy, c.sx, c.sy, 1, out);
  setup_edge(c.sx, c.sy, a.sx, a.sy, 2, out);

  // Depth plane and polygon offset, in llvmpipe's own float arithmetic (see depth_plane below).
  const WindowVertex& p0 = ccw ? v1 : v0;  // llvmpipe's vertex order for its setup: see depth_plane
  const WindowVertex& p1 = ccw ? v0 : v1;
  depth_plane(p0, p1, v2, p, out);
  out.prim = front ? 0u : kBackFacingBit;
  int32_t coef = 0;  // the OR of non-negative values is below 2^n iff each one is
  for (int k = 0; k < 3; ++k) coef |= std::abs(out.a[k]) | std::abs(out.b[k]);
  out.flags = coef < (int32_t(1) << kNarrowCoefBits) ? kNarrowEdges : 0u;
  return SetupResult::visible;
}

SHADOWLAB_ISA_END
}  // namespace raster
