// The box filter of mip generation, separable: per axis, the list of source texels under each destination
// texel with their covered fractions; a destination texel sums the products of the two lists' weights. Float
// formats with even sides take a direct 2 × 2 path with the same sums.
#include "shading/mip_chain.h"

#include <stdexcept>
#include <vector>

#include <glm/vec4.hpp>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

namespace {

struct Tap {
  int index;
  double weight;
};

// For each of the `dst` texels of an axis reduced from `src` texels, the covered source texels and weights
// (summing to 1). Destination texel d covers [d · src / dst, (d + 1) · src / dst) in source texel units.
std::vector<std::vector<Tap>> axis_taps(int src, int dst) {
  std::vector<std::vector<Tap>> taps(static_cast<size_t>(dst));
  for (int d = 0; d < dst; ++d) {
    // In units of 1/dst texel the footprint is [d · src, (d + 1) · src): integers, so overlaps are exact.
    const long lo = long(d) * src, hi = long(d + 1) * src;
    for (long k = lo / dst; k * dst < hi; ++k) {
      const long a = std::max(lo, k * dst), b = std::min(hi, (k + 1) * dst);
      if (b > a) taps[size_t(d)].push_back({int(k), double(b - a) / double(src)});
    }
  }
  return taps;
}

// The common case of a float format with both sides even: each destination texel is the mean of a 2 × 2 block,
// the same sum in double the general path makes (weights 1/2 × 1/2, the four taps in its order, row by row), so
// the same bits, without its per-texel format switch and tap lists.
template <int kFloats>
void halve_floats(const std::byte* src, size_t src_row_bytes, std::byte* dst, size_t dst_row_bytes, int dw, int dh) {
  for (int j = 0; j < dh; ++j) {
    const auto* r0 = reinterpret_cast<const float*>(src + size_t(2 * j) * src_row_bytes);
    const auto* r1 = reinterpret_cast<const float*>(src + size_t(2 * j + 1) * src_row_bytes);
    auto* out = reinterpret_cast<float*>(dst + size_t(j) * dst_row_bytes);
    for (int i = 0; i < dw; ++i) {
      const size_t a = size_t(2 * i) * kFloats, b = a + kFloats;
      for (int c = 0; c < kFloats; ++c) {
        double acc = 0.0;
        acc += 0.25 * double(r0[a + size_t(c)]);
        acc += 0.25 * double(r0[b + size_t(c)]);
        acc += 0.25 * double(r1[a + size_t(c)]);
        acc += 0.25 * double(r1[b + size_t(c)]);
        out[size_t(i) * kFloats + size_t(c)] = float(acc);
      }
    }
  }
}

}  // namespace

void box_downsample(TexelFormat format, const std::byte* src, size_t src_row_bytes, int sw, int sh, std::byte* dst,
                    size_t dst_row_bytes, int dw, int dh) {
  if (dw != mip_size(sw, 1) || dh != mip_size(sh, 1))
    throw std::invalid_argument("box_downsample: destination is not the next mip level of the source");
  if (sw == 2 * dw && sh == 2 * dh) {
    switch (format) {
      case TexelFormat::r32f: return halve_floats<1>(src, src_row_bytes, dst, dst_row_bytes, dw, dh);
      case TexelFormat::rg32f: return halve_floats<2>(src, src_row_bytes, dst, dst_row_bytes, dw, dh);
      case TexelFormat::rgba32f: return halve_floats<4>(src, src_row_bytes, dst, dst_row_bytes, dw, dh);
      default: break;
    }
  }
  const auto tx = axis_taps(sw, dw), ty = axis_taps(sh, dh);
  for (int j = 0; j < dh; ++j) {
    for (int i = 0; i < dw; ++i) {
      double acc[4] = {0, 0, 0, 0};
      for (const Tap& y : ty[size_t(j)]) {
        const std::byte* row = src + size_t(y.index) * src_row_bytes;
        for (const Tap& x : tx[size_t(i)]) {
          const glm::vec4 t = decode_texel(format, row, x.index);
          const double w = x.weight * y.weight;
          for (int c = 0; c < 4; ++c) acc[c] += w * double(t[c]);
        }
      }
      encode_texel(format, dst + size_t(j) * dst_row_bytes, i,
                   glm::vec4(float(acc[0]), float(acc[1]), float(acc[2]), float(acc[3])));
    }
  }
}

SHADOWLAB_ISA_END
}  // namespace shading
