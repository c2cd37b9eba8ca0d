// Exposure metering and development of the camera pass's luminance into an sRGB picture (see develop.h). Rows run
// on the pool, each writing only its own row or its own partial sums; the sums are added in row order, so the
// result is the same at any thread count.
#include "scenes/frame/develop.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "raster/srgb8.h"

namespace frame {

float highlight_limit(shading::ToneMap tone_map) {
  float lo = 0.0f, hi = 1000.0f;  // every operator is monotonic in grey and reaches 0.95 below 1000
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (shading::tone_map(glm::vec3(mid), tone_map).g < 0.95f ? lo : hi) = mid;
  }
  return hi;
}

namespace {

// The k-th smallest of positive finite floats (which order as their bit patterns): a histogram of the top 16 bits
// finds the bucket holding it, and only that bucket is selected in. The value does not depend on the order of
// `values`.
float kth_smallest(std::span<const float> values, size_t k) {
  std::vector<uint32_t> count(size_t(1) << 15, 0);  // the sign bit is 0
  for (const float v : values) ++count[std::bit_cast<uint32_t>(v) >> 16];
  size_t bucket = 0, below = 0;
  while (below + count[bucket] <= k) below += count[bucket++];
  std::vector<float> in_bucket;
  in_bucket.reserve(count[bucket]);
  for (const float v : values)
    if (std::bit_cast<uint32_t>(v) >> 16 == bucket) in_bucket.push_back(v);
  const auto kth = in_bucket.begin() + std::ptrdiff_t(k - below);
  std::nth_element(in_bucket.begin(), kth, in_bucket.end());
  return *kth;
}

}  // namespace

float metered_ev100(const raster::ColorTarget& radiance, shading::ToneMap tone_map, raster::ThreadPool& pool) {
  const int w = radiance.width(), h = radiance.height();
  // Each row's lit luminances at the start of its own stretch of one buffer (no per-row growth), then packed
  // down in row order.
  std::vector<float> buffer(size_t(w) * size_t(h));
  float* const all = buffer.data();
  std::vector<size_t> count(size_t(h), 0);
  std::vector<double> log_sum(size_t(h), 0.0);
  pool.parallel_for(size_t(h), [&](size_t y) {
    const float* p = radiance.row32f(int(y));
    float* out = all + y * size_t(w);
    size_t n = 0;
    double sum = 0.0;
    for (int x = 0; x < w; ++x, p += 4) {
      if (!(p[3] > 0.0f)) continue;
      const float l = shading::luminance(glm::vec3(p[0], p[1], p[2]));
      if (!(l > 0.0f) || !std::isfinite(l)) continue;
      out[n++] = l;
      sum += std::log2(double(l));
    }
    count[y] = n;
    log_sum[y] = sum;
  });
  size_t total = 0;
  double sum = 0.0;
  for (size_t y = 0; y < size_t(h); ++y) {
    const float* row = all + y * size_t(w);
    std::copy(row, row + count[y], all + total);  // never ahead of the row it reads
    total += count[y];
    sum += log_sum[y];
  }
  if (total == 0) return 0.0f;
  const double average = std::exp2(sum / double(total));
  const float p99 = kth_smallest(std::span<const float>(all, total), size_t(double(total - 1) * 0.99));
  return std::max(shading::ev100_mapping(average, 0.18),
                  shading::ev100_mapping(double(p99), double(highlight_limit(tone_map))));
}

raster::ColorTarget develop(const raster::ColorTarget& radiance, float ev100, shading::ToneMap tone_map,
                            const scenes::Background& background, raster::ThreadPool& pool) {
  const int w = radiance.width(), h = radiance.height();
  raster::ColorTarget out(w, h, raster::ColorFormat::rgba8, true);
  const float scale = shading::exposure_scale(ev100);
  // The bytes ColorTarget::write stores into this sRGB target, without its pow per channel (raster/srgb8.h).
  const raster::Srgb8Encoder srgb8;
  pool.parallel_for(size_t(h), [&](size_t row) {
    const int y = int(row);
    const float t = h > 1 ? float(y) / float(h - 1) : 0.5f;  // row 0 is the bottom of the frame
    const glm::vec3 sky = background.bottom * (1.0f - t) + background.top * t;
    const uint8_t sky8[4] = {srgb8(sky.r), srgb8(sky.g), srgb8(sky.b), 255};
    const float* p = radiance.row32f(y);
    uint8_t* q = out.row8(y);
    for (int x = 0; x < w; ++x, p += 4, q += 4) {
      if (!(p[3] > 0.0f)) {
        std::copy(sky8, sky8 + 4, q);
        continue;
      }
      glm::vec3 c(p[0], p[1], p[2]);
      for (int i = 0; i < 3; ++i)
        if (std::isnan(c[i])) c[i] = 0.0f;
      const glm::vec3 v = shading::tone_map(c * scale, tone_map);
      q[0] = srgb8(v.r), q[1] = srgb8(v.g), q[2] = srgb8(v.b), q[3] = 255;  // alpha 1: not encoded
    }
  });
  return out;
}

}  // namespace frame
