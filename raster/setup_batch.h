// Triangle setup eight at a time: the front end of a depth-only draw queues its unclipped triangles here, and
// every eight are set up together with the SIMD value types — snapping tests, culling, bounding box, edges with
// the tie rule and llvmpipe's depth plane — giving each as the compact DepthSetup, exactly what packing
// setup_triangle()'s record gives (setup.cpp, depth_setup.h). Lanes whose snapped extent is too wide for the
// int32 edge arithmetic below go through setup_triangle() and are handed over as that full record.
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "raster/assembly.h"
#include "raster/depth_setup.h"
#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/setup.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// ---- Why int32 is exact here ---------------------------------------------------------------------------------
// A lane is set up in SIMD when its snapped extent is below 2^kBatchExtentBits sub-pixel units in x and in y
// (64 pixels). Then every edge coefficient |A|, |B| < 2^14; the doubled area is a difference of two products of
// such differences, below 2^29. The edge constant is taken at the box's first pixel (mx, my), whose centre
// 256·mx + 128 lies within [xmin, xmax] for a triangle that is not outside (setup.cpp's box: the centres between
// the snapped extremes, clamped to the draw's rectangle), so E = A·(256·mx + 128 − X_a) + B·(256·my + 128 − Y_a)
// is below 2 · 2^14 · 2^14 = 2^29; F0 = floor((E − bias) / 256) is the edge's F at that pixel, which is what
// DepthSetup stores: setup.cpp's T = ceil((bias − C) / 256) equals A·mx + B·my − F0 (both are the same floor,
// shifted by the integer A·mx + B·my).
inline constexpr int kBatchExtentBits = 14;
static_assert(2 * (int64_t(1) << (2 * kBatchExtentBits)) < (int64_t(1) << 31), "area and edge values in int32");
static_assert(kBatchExtentBits <= kNarrowCoefBits, "every batched triangle is narrow: it fits a DepthSetup");
// The batch holds vertex indices as int32 (as do the outcode gathers of assembly.h), which needs fewer than 2^31
// vertices; it is used for draws of at most kBatchMaxVertices = 2^28, the bound from when its loads were gathers
// with int32 offsets of 6 · index, kept (a larger draw sets its triangles up one at a time). Its loads take
// WindowVertex as six 32-bit fields (simd::load_records6).
static_assert(sizeof(WindowVertex) == 6 * sizeof(float) && offsetof(WindowVertex, z) == 2 * sizeof(float) &&
              offsetof(WindowVertex, sx) == 4 * sizeof(float) && offsetof(WindowVertex, sy) == 5 * sizeof(float));
inline constexpr size_t kBatchMaxVertices = size_t(1) << 28;

// A batch's outcome handed over in one call (SetupBatch::flush): lane l, for each queued lane, has exactly one
// bit l among the four masks, and its record at record[l] when it is visible. Taking a batch this way instead of
// lane by lane, the depth-only front end counts its outcomes once and copies its records in one loop
// (chunk_front_end.h): measured on the 2-core AMD EPYC (Zen 4), AVX-512 path, 2 threads, shadowlab alone, five
// rounds alternating, the dragon's front end 8.76–9.12 → 8.06–8.31 ms (the draw 17.90–18.57 → 17.23–17.51 ms;
// four more rounds in a slower hour, 9.13–9.78 → 8.52–8.94 ms) and three rounds, 10⁶ triangles of ~10 px
// 12.83–12.94 → 11.93–12.25 ms.
struct SetupLanes {
  const DepthSetup* record;
  unsigned visible, culled, degenerate, outside;
};

class SetupBatch {
 public:
  SetupBatch(const SetupParams& p, const WindowVertex* win) : p_(p), win_(win) {
    has_offset_ = p.offset.factor != 0.0f || p.offset.units != 0.0f;
    if (p.format != DepthFormat::d32f) {
      const double mrd = 1.0 / double(depth_max_code(p.format));
      unorm_units_ = float(double(p.offset.units) * mrd * 2.0);  // setup.cpp: one rounding, from double
    }
  }

  // Queues the unclipped triangle with vertices (i0, i1, i2) of the window-space array; sets up eight at a time
  // and hands each result to sink(SetupResult, const Record&), in queue order, with Record a DepthSetup, or a
  // TriangleSetup for the lanes set up by setup_triangle(). The record is meaningful only when visible.
  template <class Sink>
  void push(uint32_t i0, uint32_t i1, uint32_t i2, Sink&& sink) {
    idx_[0][n_] = int32_t(i0), idx_[1][n_] = int32_t(i1), idx_[2][n_] = int32_t(i2);
    if (++n_ == 8) flush(sink);
  }

  // Queues the triangles of an assembled group whose bits are set in `lanes`, in lane order, as push() one at a
  // time would; a whole group on an empty queue is taken as it is.
  template <class Sink>
  void push_lanes(const TriangleGroup& g, unsigned lanes, Sink&& sink) {
    if (n_ == 0 && lanes == 0xFFu) {
      for (int k = 0; k < 3; ++k) simd::VecI32::load(g.vertex[k]).store_u32(reinterpret_cast<uint32_t*>(idx_[k]));
      n_ = 8;
      flush(sink);
      return;
    }
    for (; lanes != 0; lanes &= lanes - 1) {
      const int l = std::countr_zero(lanes);
      push(uint32_t(g.vertex[0][l]), uint32_t(g.vertex[1][l]), uint32_t(g.vertex[2][l]), sink);
    }
  }

  // Sets up whatever is queued (a partial batch before a clipped triangle, to keep submission order). A sink that
  // also takes a SetupLanes gets a batch whose every queued lane was set up here in that one call instead.
  template <class Sink>
  void flush(Sink&& sink) {
    if (n_ == 0) return;
    for (int l = n_; l < 8; ++l) idx_[0][l] = idx_[1][l] = idx_[2][l] = idx_[0][0];  // harmless repeats
    run();
    if constexpr (std::is_invocable_v<Sink&, const SetupLanes&>) {
      const unsigned queued = (1u << n_) - 1u;
      if ((simd_lanes_ & queued) == queued) {
        sink(SetupLanes{staged_, visible_ & queued, culled_ & queued, degenerate_ & queued, outside_ & queued});
        n_ = 0;
        return;
      }
    }
    for (int l = 0; l < n_; ++l) {
      if (!(simd_lanes_ >> l & 1u)) {
        TriangleSetup t;
        const SetupResult r = setup_triangle(win_[idx_[0][l]], win_[idx_[1][l]], win_[idx_[2][l]], p_, t);
        sink(r, t);
        continue;
      }
      sink(outcome(l), staged_[l]);
    }
    n_ = 0;
  }

 private:
  void run();
  SetupResult outcome(int l) const {
    const unsigned bit = 1u << l;
    return visible_ & bit     ? SetupResult::visible
           : culled_ & bit    ? SetupResult::culled
           : degenerate_ & bit ? SetupResult::degenerate
                               : SetupResult::outside;
  }

  SetupParams p_;
  const WindowVertex* win_;
  bool has_offset_ = false;
  float unorm_units_ = 0.0f;
  int n_ = 0;
  alignas(32) int32_t idx_[3][8];
  // Results of run(), lane by lane.
  unsigned simd_lanes_ = 0;  // lanes set up here; the others go through setup_triangle()
  unsigned visible_ = 0, culled_ = 0, degenerate_ = 0, outside_ = 0;  // each lane's outcome: its bit in one mask
  DepthSetup staged_[8];  // lane l's record, written by two 8 × 8 transposes
};

// The record as 16 dwords, two groups of eight, in the order run() builds them; the box's int16 pairs are
// dwords 9 (min_x, min_y) and 10 (max_x, max_y), low half first.
static_assert(offsetof(DepthSetup, a) == 0 && offsetof(DepthSetup, b) == 12 && offsetof(DepthSetup, f0) == 24 &&
              offsetof(DepthSetup, min_x) == 36 && offsetof(DepthSetup, min_y) == 38 &&
              offsetof(DepthSetup, max_x) == 40 && offsetof(DepthSetup, max_y) == 42 &&
              offsetof(DepthSetup, z_a0) == 44 && offsetof(DepthSetup, dzdx) == 48 &&
              offsetof(DepthSetup, dzdy) == 52 && offsetof(DepthSetup, z_offset) == 56 &&
              offsetof(DepthSetup, full) == 60 && sizeof(DepthSetup) == 64);

inline void SetupBatch::run() {
  using simd::Mask;
  using simd::VecF32;
  using simd::VecI32;
  const float* wf = reinterpret_cast<const float*>(win_);
  VecF32 x[3], y[3], z[3];
  VecI32 sx[3], sy[3];
  for (int v = 0; v < 3; ++v) simd::load_records6(wf, idx_[v], x[v], y[v], z[v], sx[v], sy[v]);
  const VecI32 xmin = simd::min(simd::min(sx[0], sx[1]), sx[2]), xmax = simd::max(simd::max(sx[0], sx[1]), sx[2]);
  const VecI32 ymin = simd::min(simd::min(sy[0], sy[1]), sy[2]), ymax = simd::max(simd::max(sy[0], sy[1]), sy[2]);
  const VecI32 limit = VecI32::splat(1 << kBatchExtentBits);
  const Mask narrow = simd::cmp_lt(xmax - xmin, limit) & simd::cmp_lt(ymax - ymin, limit);
  simd_lanes_ = narrow.bits();
  if (simd_lanes_ == 0) return;

  // Culling from the doubled signed area (exact in int32 for narrow lanes).
  const VecI32 zero = VecI32::splat(0);
  const VecI32 area2 = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
  const Mask degenerate = simd::cmp_eq(area2, zero);
  const Mask ccw = simd::cmp_lt(zero, area2);
  const Mask front = p_.front_face == FrontFace::ccw ? ccw : and_not(Mask::all(), ccw);
  const Mask culled = p_.cull == CullMode::back    ? and_not(Mask::all(), front)
                      : p_.cull == CullMode::front ? front
                                                   : Mask::from_bits(0);

  // Pixel bounding box, as setup.cpp.
  constexpr int32_t half = kSubpixelScale / 2;
  const VecI32 min_x = simd::max(VecI32::splat(p_.clip.x0),
                                 simd::shift_right<kSubpixelBits>(xmin + VecI32::splat(kSubpixelScale - 1 - half)));
  const VecI32 max_x = simd::min(VecI32::splat(p_.clip.x1), simd::shift_right<kSubpixelBits>(xmax - VecI32::splat(half)));
  const VecI32 min_y = simd::max(VecI32::splat(p_.clip.y0),
                                 simd::shift_right<kSubpixelBits>(ymin + VecI32::splat(kSubpixelScale - 1 - half)));
  const VecI32 max_y = simd::min(VecI32::splat(p_.clip.y1), simd::shift_right<kSubpixelBits>(ymax - VecI32::splat(half)));
  const Mask outside = simd::cmp_lt(max_x, min_x) | simd::cmp_lt(max_y, min_y);

  // The outcome in setup_triangle()'s order of tests: degenerate before culled before outside.
  degenerate_ = degenerate.bits();
  culled_ = culled.bits() & ~degenerate_;
  outside_ = outside.bits() & ~(culled_ | degenerate_);
  visible_ = ~(outside_ | culled_ | degenerate_) & 0xFFu;
  VecF32 rec[16];  // the records' dwords (see the static_assert above), lane by lane
  // Visible boxes lie within [0, kMaxTargetSize − 1] (limits.h), so the int16 halves are the low bits.
  rec[9] = simd::bitcast_f32(min_x | simd::shift_left<16>(min_y));
  rec[10] = simd::bitcast_f32(max_x | simd::shift_left<16>(max_y));
  rec[15] = simd::bitcast_f32(VecI32::splat(int32_t(kNoFullSetup)));

  // Edges of the counter-clockwise ordering (a, b, c) = (v0, v1, v2) or (v0, v2, v1), with the tie rule.
  const VecI32 ex[3] = {sx[0], simd::select(ccw, sx[2], sx[1]), simd::select(ccw, sx[1], sx[2])};
  const VecI32 ey[3] = {sy[0], simd::select(ccw, sy[2], sy[1]), simd::select(ccw, sy[1], sy[2])};
  const VecI32 cx = simd::shift_left<kSubpixelBits>(min_x) + VecI32::splat(half);  // centre of the box's first pixel
  const VecI32 cy = simd::shift_left<kSubpixelBits>(min_y) + VecI32::splat(half);
  for (int k = 0; k < 3; ++k) {
    const VecI32 xa = ex[k], ya = ey[k], xb = ex[(k + 1) % 3], yb = ey[(k + 1) % 3];
    const VecI32 A = ya - yb, B = xb - xa;
    const Mask inclusive = simd::cmp_lt(zero, A) | (simd::cmp_eq(A, zero) & simd::cmp_lt(zero, B));
    const VecI32 bias = simd::select(inclusive, VecI32::splat(1), zero);
    const VecI32 E = A * (cx - xa) + B * (cy - ya);
    rec[k] = simd::bitcast_f32(A);
    rec[3 + k] = simd::bitcast_f32(B);
    rec[6 + k] = simd::bitcast_f32(simd::shift_right<kSubpixelBits>(E - bias));  // F0
  }

  // Depth plane and polygon offset in llvmpipe's vertex order and float operations (setup.cpp, depth_plane).
  const VecF32 p0x = simd::select(ccw, x[0], x[1]), p0y = simd::select(ccw, y[0], y[1]);
  const VecF32 p0z = simd::select(ccw, z[0], z[1]);
  const VecF32 p1x = simd::select(ccw, x[1], x[0]), p1y = simd::select(ccw, y[1], y[0]);
  const VecF32 p1z = simd::select(ccw, z[1], z[0]);
  const VecF32 dx01 = p0x - p1x, dy01 = p0y - p1y;
  const VecF32 dx20 = x[2] - p0x, dy20 = y[2] - p0y;
  const VecF32 e = dx01 * dy20, f = dy01 * dx20;
  const VecF32 ooa = simd::div(VecF32::splat(1.0f), e - f);
  const VecF32 dx20o = dx20 * ooa, dy20o = dy20 * ooa, dx01o = dx01 * ooa, dy01o = dy01 * ooa;
  const VecF32 dz01 = p0z - p1z, dz20 = z[2] - p0z;
  const VecF32 dzdx = dz01 * dy20o - dz20 * dy01o;
  const VecF32 dzdy = dz20 * dx01o - dz01 * dx20o;
  const VecF32 x0c = p0x - VecF32::splat(0.5f), y0c = p0y - VecF32::splat(0.5f);
  rec[11] = p0z - (dzdx * x0c + dzdy * y0c);
  rec[12] = dzdx;
  rec[13] = dzdy;
  VecF32 z_offset = VecF32::splat(0.0f);
  if (has_offset_) {
    const VecI32 abs_bits = VecI32::splat(0x7fffffff);
    auto fabs = [&](VecF32 v) { return simd::bitcast_f32(simd::bitcast_i32(v) & abs_bits); };
    const VecF32 ox = fabs((dz20 * dy01 - dy20 * dz01) * ooa);
    const VecF32 oy = fabs((dx20 * dz01 - dz20 * dx01) * ooa);
    const VecF32 m = simd::select(simd::cmp_lt(oy, ox) | simd::cmp_neq(ox, ox), oy, ox);  // LLVMRealUGT select
    const VecF32 mult = m * VecF32::splat(p_.offset.factor);
    VecF32 units = VecF32::splat(unorm_units_);
    if (p_.format == DepthFormat::d32f) {
      auto std_max = [](VecF32 a, VecF32 b) { return simd::select(simd::cmp_lt(a, b), a, b); };  // (a < b) ? b : a
      const VecF32 zmax = std_max(fabs(z[2]), std_max(fabs(p0z), fabs(p1z)));
      const VecI32 bits = (simd::bitcast_i32(zmax) & VecI32::splat(0x7f800000)) - VecI32::splat(23 << 23);
      units = simd::bitcast_f32(simd::max(bits, zero)) * VecF32::splat(p_.offset.units);
    }
    z_offset = units + mult;
  }
  rec[14] = z_offset;
  float* out = reinterpret_cast<float*>(staged_);
  for (int g = 0; g < 2; ++g) {
    VecF32 group[8];
    for (int i = 0; i < 8; ++i) group[i] = rec[8 * g + i];
    simd::transpose8(group);
    for (int l = 0; l < 8; ++l) group[l].store(out + l * 16 + 8 * g);
  }
}

SHADOWLAB_ISA_END
}  // namespace raster
