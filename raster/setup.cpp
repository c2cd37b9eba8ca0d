// Triangle setup (see setup.h): viewport transform, snapping, culling, integer edges with the tie rule,
// bounding box and depth plane. Integer ranges are derived in limits.h.
#include "raster/setup.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/limits.h"

namespace raster {

SetupParams make_setup_params(const DrawState& s, int tw, int th, DepthFormat format) {
  const Rect vp = s.viewport.value_or(Rect{0, 0, tw, th});
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
    case DepthFormat::d16: return 2.0f / 65535.0f;
    case DepthFormat::d24: return 2.0f / 16777215.0f;
    case DepthFormat::d32f: {
      if (!(max_depth > 0.0f)) return std::ldexp(1.0f, -126 - 23);
      int e2 = 0;
      std::frexp(max_depth, &e2);  // max_depth = f · 2^e2 with f in [0.5, 1): IEEE exponent e = e2 − 1
      return std::ldexp(1.0f, (e2 - 1) - 23);
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

  // Depth plane through the unsnapped float window positions (as llvmpipe sets it up: with snapped positions
  // depths differ from it by up to |dz/dx| / 512), in double, evaluated at the box's first pixel centre.
  const double x0 = v0.x, y0 = v0.y;
  const double x1 = double(v1.x) - x0, y1 = double(v1.y) - y0;
  const double x2 = double(v2.x) - x0, y2 = double(v2.y) - y0;
  const double z1 = double(v1.z) - v0.z, z2 = double(v2.z) - v0.z;
  const double inv_det = 1.0 / (x1 * y2 - x2 * y1);
  const double dzdx = (z1 * y2 - z2 * y1) * inv_det;
  const double dzdy = (z2 * x1 - z1 * x2) * inv_det;
  double z_ref = v0.z + dzdx * (out.min_x + 0.5 - x0) + dzdy * (out.min_y + 0.5 - y0);
  if (p.offset.factor != 0.0f || p.offset.units != 0.0f) {
    const double m = std::max(std::abs(dzdx), std::abs(dzdy));
    const float zmax = std::max({v0.z, v1.z, v2.z});
    z_ref += m * p.offset.factor + double(polygon_offset_r(p.format, zmax)) * p.offset.units;
  }
  out.z_ref = float(z_ref);
  out.dzdx = float(dzdx);
  out.dzdy = float(dzdy);
  out.prim = front ? 0u : kBackFacingBit;
  return SetupResult::visible;
}

}  // namespace raster
