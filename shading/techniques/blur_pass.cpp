// The encode and blur passes of the filterable maps (see blur_pass.h): full-screen triangles with a fragment
// shader each, drawn without depth into an RGBA32F target.
#include "shading/techniques/blur_pass.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "shading/techniques/full_screen_pass.h"

namespace shading::tech {

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

// The box filter along one axis over the first kChannels components, summed in tap order. The wide path
// gathers, per channel, the texels its eight lanes share (a row segment of 4 + 2 radius texels for each of its
// two rows, or a column of 2 + 2 radius rows of 4 texels) once, then adds one eight-lane vector per tap: the
// same additions in the same order as texel(), so both paths agree bit for bit.
template <int kChannels, bool kVertical>
struct BlurShader : FullScreenShader<BlurShader<kChannels, kVertical>> {
  static constexpr int kMaxRadius = 16;
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
      const float* t = src->row32f(yy) + size_t(xx) * 4;
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
    constexpr int kSpan = 4 + 2 * kMaxRadius;
    // kVertical: line[c][i] holds rows y0 − radius + i, 4 texels each (i in [0, 2 + 2 radius)).
    // Horizontal: line[c][r][i] holds texel x0 − radius + i of row y0 + r.
    alignas(32) float line[kChannels][2][kSpan + 8];
    alignas(32) float col[kChannels][2 + 2 * kMaxRadius][4];
    auto clamp_x = [&](int x) { return std::clamp(x, 0, w - 1); };
    auto clamp_y = [&](int y) { return std::clamp(y, 0, h - 1); };
    // The source lines the block to the right (8 pixels on) will read, asked for now: the loads of a pass over
    // a 2048² RGBA32F target waited on memory (53 % of the horizontal pass's samples on one load). A prefetch
    // never faults, so addresses past a row's end need no test.
    const int ahead = clamp_x(x0 + 8 + radius + 3);
    if constexpr (kVertical) {
      for (int i = 0; i < 2 + 2 * radius; ++i)
        __builtin_prefetch(src->row32f(clamp_y(y0 - radius + i)) + size_t(ahead) * 4, 0, 3);
    } else {
      for (int r = 0; r < 2; ++r) __builtin_prefetch(src->row32f(clamp_y(y0 + r)) + size_t(ahead) * 4, 0, 3);
    }
    if constexpr (kVertical) {
      for (int i = 0; i < 2 + 2 * radius; ++i) {
        const float* row = src->row32f(clamp_y(y0 - radius + i));
        for (int l = 0; l < 4; ++l) {
          const float* t = row + size_t(clamp_x(x0 + l)) * 4;
          for (int c = 0; c < kChannels; ++c) col[c][i][l] = t[c];
        }
      }
    } else {
      for (int r = 0; r < 2; ++r) {
        const float* row = src->row32f(clamp_y(y0 + r));
        for (int i = 0; i < 4 + 2 * radius; ++i) {
          const float* t = row + size_t(clamp_x(x0 - radius + i)) * 4;
          for (int c = 0; c < kChannels; ++c) line[c][r][i] = t[c];
        }
      }
    }
    for (int c = 0; c < 4; ++c) out.color[size_t(c)] = VecF32::splat(0.0f);
    for (int c = 0; c < kChannels; ++c) {
      VecF32 sum = VecF32::splat(0.0f);
      for (int k = 0; k <= 2 * radius; ++k) {
        if constexpr (kVertical) sum = sum + raster::simd::load_rows4(col[c][k], col[c][k + 1]);
        else sum = sum + raster::simd::load_rows4(line[c][0] + k, line[c][1] + k);
      }
      out.color[size_t(c)] = sum * VecF32::splat(scale);
    }
  }
};

void check_float_target(const raster::ColorTarget& t, const char* what) {
  if (t.format() != raster::ColorFormat::rgba32f)
    throw std::logic_error(std::string(what) + ": the filterable map passes need an rgba32f target");
}

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

raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, const LightDepth& depth,
                                 const MomentParams& p, raster::ColorTarget& out) {
  return encode_moments(renderer, src, raster::Rect{0, 0, src.width(), src.height()}, depth, p, out);
}

raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, raster::Rect region,
                                 const LightDepth& depth, const MomentParams& p, raster::ColorTarget& out) {
  check_float_target(out, "encode_moments");
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
                            int radius, int channels, bool vertical) {
  check_float_target(src, "blur_pass");
  check_float_target(dst, "blur_pass");
  if (&src == &dst) throw std::logic_error("blur_pass: source and destination must differ");
  if (src.width() != dst.width() || src.height() != dst.height())
    throw std::logic_error("blur_pass: source and destination must have the same size");
  if (radius < 0 || radius > 16) throw std::logic_error("blur_pass: radius outside 0..16");
  switch (channels) {
    case 1: return blur_with<1>(renderer, src, dst, radius, vertical);
    case 2: return blur_with<2>(renderer, src, dst, radius, vertical);
    case 4: return blur_with<4>(renderer, src, dst, radius, vertical);
    default: throw std::logic_error("blur_pass: channels must be 1, 2 or 4");
  }
}

raster::DrawStats blur_map(raster::Renderer& renderer, raster::ColorTarget& map, raster::ColorTarget& scratch,
                           int radius, int channels) {
  raster::DrawStats stats;
  if (radius == 0) return stats;
  stats += blur_pass(renderer, map, scratch, radius, channels, false);
  stats += blur_pass(renderer, scratch, map, radius, channels, true);
  return stats;
}

}  // namespace shading::tech
