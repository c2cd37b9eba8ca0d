// Exposure metering and development of the camera pass's luminance into an sRGB picture (see develop.h). Rows run
// on the pool, each writing only its own row or its own partial sums; the sums are added in row order, so the
// result is the same at any thread count.
#include "scenes/frame/develop.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace frame {

float highlight_limit(shading::ToneMap tone_map) {
  float lo = 0.0f, hi = 1000.0f;  // every operator is monotonic in grey and reaches 0.95 below 1000
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (shading::tone_map(glm::vec3(mid), tone_map).g < 0.95f ? lo : hi) = mid;
  }
  return hi;
}

float metered_ev100(const raster::ColorTarget& radiance, shading::ToneMap tone_map, raster::ThreadPool& pool) {
  const int h = radiance.height();
  std::vector<std::vector<float>> lum(static_cast<size_t>(h));  // each row's lit luminances
  std::vector<double> log_sum(size_t(h), 0.0);
  pool.parallel_for(size_t(h), [&](size_t y) {
    const float* p = radiance.row32f(int(y));
    for (int x = 0; x < radiance.width(); ++x, p += 4) {
      if (!(p[3] > 0.0f)) continue;
      const float l = shading::luminance(glm::vec3(p[0], p[1], p[2]));
      if (!(l > 0.0f) || !std::isfinite(l)) continue;
      lum[y].push_back(l);
      log_sum[y] += std::log2(double(l));
    }
  });
  std::vector<float> all;
  double sum = 0.0;
  for (size_t y = 0; y < size_t(h); ++y) {
    all.insert(all.end(), lum[y].begin(), lum[y].end());
    sum += log_sum[y];
  }
  if (all.empty()) return 0.0f;
  const double average = std::exp2(sum / double(all.size()));
  // The k-th smallest value does not depend on the order the rows were gathered in.
  const auto p99 = all.begin() + std::ptrdiff_t(double(all.size() - 1) * 0.99);
  std::nth_element(all.begin(), p99, all.end());
  return std::max(shading::ev100_mapping(average, 0.18),
                  shading::ev100_mapping(double(*p99), double(highlight_limit(tone_map))));
}

raster::ColorTarget develop(const raster::ColorTarget& radiance, float ev100, shading::ToneMap tone_map,
                            const scenes::Background& background, raster::ThreadPool& pool) {
  const int w = radiance.width(), h = radiance.height();
  raster::ColorTarget out(w, h, raster::ColorFormat::rgba8, true);
  const float scale = shading::exposure_scale(ev100);
  pool.parallel_for(size_t(h), [&](size_t row) {
    const int y = int(row);
    const float t = h > 1 ? float(y) / float(h - 1) : 0.5f;  // row 0 is the bottom of the frame
    const glm::vec4 sky(background.bottom * (1.0f - t) + background.top * t, 1.0f);
    const float* p = radiance.row32f(y);
    for (int x = 0; x < w; ++x, p += 4) {
      if (!(p[3] > 0.0f)) {
        out.write(x, y, sky);
        continue;
      }
      glm::vec3 c(p[0], p[1], p[2]);
      for (int i = 0; i < 3; ++i)
        if (std::isnan(c[i])) c[i] = 0.0f;
      out.write(x, y, glm::vec4(shading::tone_map(c * scale, tone_map), 1.0f));
    }
  });
  return out;
}

}  // namespace frame
