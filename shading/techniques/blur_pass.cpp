// The encode and blur passes of the filterable maps (see blur_pass.h): full-screen triangles with a fragment
// shader each, drawn without depth into a float target of the moment kind's channels.
#include "shading/techniques/blur_pass.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "shading/techniques/full_screen_pass.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

using raster::simd::VecF32;

struct EncodeShader : FullScreenShader<EncodeShader> {
  const raster::DepthTarget* src = nullptr;
  raster::Rect region;
  LightDepth depth;
  MomentParams params;
  glm::vec4 texel(int x, int y) const {
    // Helper lanes of the last quad pair may lie past the edge: they read the edge texel.
    x = std::min(x, region.width - 1), y = std::min(y, region.height - 1);
    return moments(params, depth.from_window(src->value(region.x + x, region.y + y)));
  }
};

// The box filter along one axis over the kChannels floats of a float target's texel, summed in tap order.
// The wide path sums the taps in the target's own interleaved layout: each tap of a row of four output texels
// is one unaligned load of those four texels' worth of floats (horizontal: shifted along the source row;
// vertical: the same columns of another row), added in the same order as texel() adds them, then split into
// channels. Every float is the same sum as texel()'s, so both paths agree bit for bit. A group whose taps
// would need clamping (within radius + 3 texels of an edge) or that has helper lanes past the edge takes the
// per-texel path.
template <int kChannels, bool kVertical>
struct BlurShader : FullScreenShader<BlurShader<kChannels, kVertical>> {
  using Base = FullScreenShader<BlurShader<kChannels, kVertical>>;
  const raster::ColorTarget* src = nullptr;
  int radius = 1;
  float scale = 1.0f;  // 1 / (2 radius + 1)
  glm::vec4 texel(int x, int y) const {
    const int w = src->width(), h = src->height();
    x = std::min(x, w - 1), y = std::min(y, h - 1);
    float sum[kChannels] = {};
    for (int k = -radius; k <= radius; ++k) {
      const int xx = kVertical ? x : std::clamp(x + k, 0, w - 1);
      const int yy = kVertical ? std::clamp(y + k, 0, h - 1) : y;
      const float* t = src->row32f(yy) + size_t(xx) * kChannels;
      for (int c = 0; c < kChannels; ++c) sum[c] += t[c];
    }
    glm::vec4 out(0.0f);
    for (int c = 0; c < kChannels; ++c) out[c] = sum[c] * scale;
    return out;
  }
  void fragment_pair(const raster::QuadPairIn<raster::NoVaryings>& q, raster::QuadPairOut& out) const {
    const int w = src->width(), h = src->height();
    alignas(32) float fx[8], fy[8];
    q.frag_x.store(fx), q.frag_y.store(fy);
    const int x0 = int(fx[0]), y0 = int(fy[0]);
    const bool inside = kVertical ? x0 + 3 < w : (x0 - radius >= 0 && x0 + 3 + radius < w && y0 + 1 < h);
    if (!inside) return Base::fragment_pair(q, out);
    // The pipeline walks a tile's 8×8 blocks left to right, then the next row of blocks: the source lines that
    // row will read first, eight rows up, are asked for now (the hardware's prefetch does not follow 64-texel
    // runs one row pitch apart; without this three quarters of the pass waited on these loads). A prefetch
    // never faults, so rows past the top need no test.
    const int ahead = y0 + 8 + (kVertical ? radius : 0);
    for (int r = 0; r < 2; ++r)
      __builtin_prefetch(src->row32f(std::min(ahead + r, h - 1)) + size_t(x0) * kChannels, 0, 3);
    // Four texels of kChannels floats: one vector of eight floats per two texels (or four floats, half a
    // vector, for one channel).
    constexpr int kVectors = kChannels == 4 ? 2 : 1;
    VecF32 sum[2][kVectors];
    for (auto& r : sum)
      for (auto& v : r) v = VecF32::splat(0.0f);
    if constexpr (kChannels == 1) {
      // One channel: both rows' four texels fit one vector, lanes as the pipeline orders them.
      for (int k = -radius; k <= radius; ++k) {
        const float* r0 = kVertical ? src->row32f(std::clamp(y0 + k, 0, h - 1)) + x0 : src->row32f(y0) + x0 + k;
        const float* r1 = kVertical ? src->row32f(std::clamp(y0 + 1 + k, 0, h - 1)) + x0 : src->row32f(y0 + 1) + x0 + k;
        sum[0][0] = sum[0][0] + raster::simd::load_rows4(r0, r1);
      }
      out.color[0] = sum[0][0] * VecF32::splat(scale);
      for (int c = 1; c < 4; ++c) out.color[size_t(c)] = VecF32::splat(0.0f);
      return;
    } else {
      for (int r = 0; r < 2; ++r) {
        for (int k = -radius; k <= radius; ++k) {
          const float* t = kVertical ? src->row32f(std::clamp(y0 + r + k, 0, h - 1)) + size_t(x0) * kChannels
                                     : src->row32f(y0 + r) + ptrdiff_t(x0 + k) * kChannels;
          for (int v = 0; v < kVectors; ++v) sum[r][v] = sum[r][v] + VecF32::load(t + 8 * v);
        }
      }
      auto& c = out.color;
      if constexpr (kChannels == 2) {
        raster::simd::deinterleave_rows4(sum[0][0], sum[1][0], c[0], c[1]);
        c[2] = c[3] = VecF32::splat(0.0f);
      } else {
        raster::simd::deinterleave_rows4(sum[0][0], sum[0][1], sum[1][0], sum[1][1], c[0], c[1], c[2], c[3]);
      }
      for (int i = 0; i < kChannels; ++i) c[size_t(i)] = c[size_t(i)] * VecF32::splat(scale);
    }
  }
};

template <int kChannels>
raster::DrawStats blur_with(raster::Renderer& renderer, const raster::ColorTarget& src, raster::ColorTarget& dst,
                            int radius, bool vertical) {
  const float scale = 1.0f / float(2 * radius + 1);
  auto draw = [&]<bool kVertical>() {
    BlurShader<kChannels, kVertical> s;
    s.src = &src, s.radius = radius, s.scale = scale;
    return draw_full_screen(renderer, dst, s);
  };
  return vertical ? draw.template operator()<true>() : draw.template operator()<false>();
}

}  // namespace

raster::ColorFormat moment_format(MomentKind kind) {
  switch (moment_channels(kind)) {
    case 1: return raster::ColorFormat::r32f;
    case 2: return raster::ColorFormat::rg32f;
    default: return raster::ColorFormat::rgba32f;
  }
}

raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, const LightDepth& depth,
                                 const MomentParams& p, raster::ColorTarget& out) {
  return encode_moments(renderer, src, raster::Rect{0, 0, src.width(), src.height()}, depth, p, out);
}

raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, raster::Rect region,
                                 const LightDepth& depth, const MomentParams& p, raster::ColorTarget& out) {
  if (out.format() != moment_format(p.kind))
    throw std::logic_error("encode_moments: the moment target's format must be moment_format(kind)");
  if (region.x < 0 || region.y < 0 || region.width < 1 || region.height < 1 ||
      region.x + region.width > src.width() || region.y + region.height > src.height())
    throw std::logic_error("encode_moments: the region lies outside the depth map");
  if (out.width() != region.width || out.height() != region.height)
    throw std::logic_error("encode_moments: the moment target must have the region's size");
  EncodeShader s;
  s.src = &src, s.region = region, s.depth = depth, s.params = p;
  return draw_full_screen(renderer, out, s);
}

raster::DrawStats blur_pass(raster::Renderer& renderer, const raster::ColorTarget& src, raster::ColorTarget& dst,
                            int radius, bool vertical) {
  if (src.channels() == 0) throw std::logic_error("blur_pass: the source must be a float target");
  if (&src == &dst) throw std::logic_error("blur_pass: source and destination must differ");
  if (src.format() != dst.format() || src.width() != dst.width() || src.height() != dst.height())
    throw std::logic_error("blur_pass: source and destination must have the same size and format");
  if (radius < 0 || radius > 16) throw std::logic_error("blur_pass: radius outside 0..16");
  switch (src.channels()) {
    case 1: return blur_with<1>(renderer, src, dst, radius, vertical);
    case 2: return blur_with<2>(renderer, src, dst, radius, vertical);
    default: return blur_with<4>(renderer, src, dst, radius, vertical);
  }
}

raster::DrawStats blur_map(raster::Renderer& renderer, raster::ColorTarget& map, raster::ColorTarget& scratch,
                           int radius) {
  raster::DrawStats stats;
  if (radius == 0) return stats;
  stats += blur_pass(renderer, map, scratch, radius, false);
  stats += blur_pass(renderer, scratch, map, radius, true);
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
