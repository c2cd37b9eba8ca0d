// The ideal PCSS profile across a straight occluder edge, for the penumbra tests (classic map and cascades):
// 16 points of the Poisson disc, each turned uniformly, a kernel of radius k over a sharp edge, and the distance
// between its 10 % and 90 % crossings.
#pragma once
#include <cmath>

#include "shading/techniques/poisson.h"

namespace techtest {

// Tap i at radius r_i lands lit with probability P(x + r_i k cos φ > 0).
inline float ideal_pcss_width(float k) {
  auto profile = [&](float x) {
    float v = 0.0f;
    for (const glm::vec2& d : shading::tech::kPoissonDisk) {
      const float r = std::sqrt(d.x * d.x + d.y * d.y) * k;
      if (x >= r) v += 1.0f;
      else if (x > -r) v += 1.0f - std::acos(x / r) / 3.14159265f;
    }
    return v / 16.0f;
  };
  float x10 = NAN, x90 = NAN;
  for (float x = -2.0f * k; x <= 2.0f * k; x += k / 2000.0f) {
    if (std::isnan(x10) && profile(x) >= 0.1f) x10 = x;
    if (std::isnan(x90) && profile(x) >= 0.9f) x90 = x;
  }
  return x90 - x10;
}

// A measured profile's 10-90 % width: x steps from -reach to reach; at each, the visibility is averaged over
// `rows` pixels, vis(x, j) being pixel j's (each pixel its own turn of the disc, frag (7 j + 3, j)).
template <class Vis>
float measured_width(float reach, float step, int rows, Vis vis) {
  float x10 = NAN, x90 = NAN;
  for (float x = -reach; x <= reach; x += step) {
    float v = 0.0f;
    for (int j = 0; j < rows; ++j) v += vis(x, j, glm::vec2(float(j * 7 + 3), float(j)));
    v /= float(rows);
    if (std::isnan(x10) && v >= 0.1f) x10 = x;
    if (std::isnan(x90) && v >= 0.9f) x90 = x;
  }
  return x90 - x10;
}

}  // namespace techtest
