// Exposure metering and development of the camera pass's luminance into an sRGB picture (see develop.h). Rows run
// on the pool, each writing only its own row or its own partial sums; the sums are added in row order, so the
// result is the same at any thread count.
#include "scenes/frame/develop.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "raster/srgb8.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

float highlight_limit(shading::ToneMap tone_map) {
  float lo = 0.0f, hi = 1000.0f;  // every operator is monotonic in grey and reaches 0.95 below 1000
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (shading::tone_map(glm::vec3(mid), tone_map).g < 0.95f ? lo : hi) = mid;
  }
  return hi;
}

namespace {

// Positive finite floats order as their bit patterns; their top 13 bits (the sign bit 0, the exponent and 4 bits
// of mantissa: 1/16 of an octave) pick one of these buckets, 16 KiB of counts per band of rows.
constexpr size_t kBuckets = size_t(1) << 12;
uint32_t bucket_of(float v) { return std::bit_cast<uint32_t>(v) >> 19; }

// A drawn pixel's luminance when it counts for metering (alpha > 0, luminance positive and finite), else 0.
float metered_luminance(const float* p) {
  if (!(p[3] > 0.0f)) return 0.0f;
  const float l = shading::luminance(glm::vec3(p[0], p[1], p[2]));
  return l > 0.0f && std::isfinite(l) ? l : 0.0f;
}

// The dither of pixel (x, y), in 8-bit codes, in [-1/4, 1/4): an integer hash of the position (the same at any
// thread count and on any machine), one value for the three channels so that it never tints.
float dither_at(uint32_t x, uint32_t y) {
  uint32_t h = x * 0x9E3779B1u ^ (y + 0x7F4A7C15u) * 0x85EBCA77u;
  h ^= h >> 16, h *= 0x7FEB352Du, h ^= h >> 15, h *= 0x846CA68Bu, h ^= h >> 16;
  return float(h >> 8) * (0.5f / 16777216.0f) - 0.25f;
}

// The code of linear value `v` dithered by `d` (dither_at): the code the encoder stores, moved to its neighbour
// when v lies within |d| of the edge between them (v's place inside its code's interval taken linearly between
// the encoder's thresholds), so every pixel is one of the two codes around its exact encoded value. 0 and 1 and
// beyond stay exact (black and white are not speckled).
uint8_t dithered(const raster::Srgb8Encoder& srgb8, float v, float d) {
  const unsigned c = srgb8(v);
  if (!(v > 0.0f) || v >= 1.0f) return uint8_t(c);
  float f;  // v's place in its code's interval of encoded values [c - 1/2, c + 1/2), 0 at its lower edge
  if (c == 0)
    f = 0.5f + 0.5f * v / srgb8.threshold(1);  // sRGB is linear below its first threshold
  else if (c == 255)
    f = 0.5f * (v - srgb8.threshold(255)) / (1.0f - srgb8.threshold(255));
  else
    f = (v - srgb8.threshold(c)) / (srgb8.threshold(c + 1) - srgb8.threshold(c));
  const float g = f + d;
  return uint8_t(g >= 1.0f ? c + 1 : g < 0.0f ? c - 1 : c);
}

}  // namespace

float metered_ev100(const raster::ColorTarget& radiance, shading::ToneMap tone_map, raster::ThreadPool& pool) {
  const int w = radiance.width(), h = radiance.height();
  // Rows in bands, one histogram of the lit luminances per band (counts add up to the same whatever the bands),
  // and each row's count and sum of log2 (added in row order). No copy of the values: a frame-sized buffer cost
  // more in fresh pages than the metering itself.
  const size_t bands = std::min(size_t(h), size_t(std::max(pool.threads(), 1)) * 2);
  std::vector<std::vector<uint32_t>> histogram(bands);
  std::vector<size_t> count(size_t(h), 0);
  std::vector<double> log_sum(size_t(h), 0.0);
  auto band_rows = [&](size_t b) { return std::pair(b * size_t(h) / bands, (b + 1) * size_t(h) / bands); };
  pool.parallel_for(bands, [&](size_t b) {
    std::vector<uint32_t>& hist = histogram[b];
    hist.assign(kBuckets, 0);
    const auto [y0, y1] = band_rows(b);
    for (size_t y = y0; y < y1; ++y) {
      const float* p = radiance.row32f(int(y));
      size_t n = 0;
      double sum = 0.0;
      for (int x = 0; x < w; ++x, p += 4) {
        const float l = metered_luminance(p);
        if (l == 0.0f) continue;
        ++n;
        ++hist[bucket_of(l)];
        sum += std::log2(double(l));
      }
      count[y] = n;
      log_sum[y] = sum;
    }
  });
  size_t total = 0;
  double sum = 0.0;
  for (size_t y = 0; y < size_t(h); ++y) total += count[y], sum += log_sum[y];
  if (total == 0) return 0.0f;
  const double average = std::exp2(sum / double(total));

  // The 99th percentile: the bucket holding the k-th smallest, then only that bucket's values selected in (the
  // k-th value does not depend on the order they are gathered in).
  const size_t k = size_t(double(total - 1) * 0.99);
  size_t bucket = 0, below = 0;
  for (;; ++bucket) {
    size_t in = 0;
    for (const std::vector<uint32_t>& hist : histogram) in += hist[bucket];
    if (below + in > k) break;
    below += in;
  }
  std::vector<std::vector<float>> gathered(bands);
  pool.parallel_for(bands, [&](size_t b) {
    gathered[b].reserve(histogram[b][bucket]);
    const auto [y0, y1] = band_rows(b);
    for (size_t y = y0; y < y1; ++y) {
      const float* p = radiance.row32f(int(y));
      for (int x = 0; x < w; ++x, p += 4)
        if (const float l = metered_luminance(p); l != 0.0f && bucket_of(l) == bucket) gathered[b].push_back(l);
    }
  });
  std::vector<float> in_bucket;
  for (const std::vector<float>& g : gathered) in_bucket.insert(in_bucket.end(), g.begin(), g.end());
  const auto kth = in_bucket.begin() + std::ptrdiff_t(k - below);
  std::nth_element(in_bucket.begin(), kth, in_bucket.end());
  const float p99 = *kth;
  return std::max(shading::ev100_mapping(average, 0.18),
                  shading::ev100_mapping(double(p99), double(highlight_limit(tone_map))));
}

raster::ColorTarget develop(const raster::ColorTarget& radiance, float ev100, shading::ToneMap tone_map,
                            const scenes::Background& background, raster::ThreadPool& pool) {
  raster::ColorTarget out(radiance.width(), radiance.height(), raster::ColorFormat::rgba8, true);
  develop_into(out, radiance, ev100, tone_map, background, pool);
  return out;
}

void develop_into(raster::ColorTarget& out, const raster::ColorTarget& radiance, float ev100,
                  shading::ToneMap tone_map, const scenes::Background& background, raster::ThreadPool& pool) {
  const int w = radiance.width(), h = radiance.height();
  if (out.width() != w || out.height() != h || out.format() != raster::ColorFormat::rgba8 || !out.srgb())
    throw std::invalid_argument("develop_into: the picture must be an sRGB RGBA8 target of the radiance's size");
  const float scale = shading::exposure_scale(ev100);
  // The bytes ColorTarget::write stores into this sRGB target, without its pow per channel (raster/srgb8.h), then
  // dithered by a quarter code.
  const raster::Srgb8Encoder srgb8;
  pool.parallel_for(size_t(h), [&](size_t row) {
    const int y = int(row);
    const float t = h > 1 ? float(y) / float(h - 1) : 0.5f;  // row 0 is the bottom of the frame
    const glm::vec3 sky = background.bottom * (1.0f - t) + background.top * t;
    const float* p = radiance.row32f(y);
    uint8_t* q = out.row8(y);
    for (int x = 0; x < w; ++x, p += 4, q += 4) {
      const float d = dither_at(uint32_t(x), uint32_t(y));
      glm::vec3 v = sky;
      if (p[3] > 0.0f) {
        glm::vec3 c(p[0], p[1], p[2]);
        for (int i = 0; i < 3; ++i)
          if (std::isnan(c[i])) c[i] = 0.0f;
        v = shading::tone_map(c * scale, tone_map);
      }
      q[0] = dithered(srgb8, v.r, d), q[1] = dithered(srgb8, v.g, d), q[2] = dithered(srgb8, v.b, d);
      q[3] = 255;  // alpha 1: not encoded
    }
  });
}

SHADOWLAB_ISA_END
}  // namespace frame
