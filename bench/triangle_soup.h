// Deterministic random triangle soups for the depth-pass benchmarks: triangles of a chosen area in pixels,
// scattered over a square map, given directly in clip space (w = 1) with random depths and orientations.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/vec4.hpp>

namespace bench {

struct Soup {
  std::vector<glm::vec4> positions;  // clip space
  std::vector<uint32_t> indices;
};

// `count` triangles of about `area` pixels on a `size`×`size` map, each its own three vertices (indexed).
inline Soup make_soup(size_t count, double area, int size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  // An equilateral triangle of the given area has circumradius R with area = (3√3/4) R².
  const double R = std::sqrt(area * 4.0 / (3.0 * std::sqrt(3.0)));
  Soup s;
  s.positions.reserve(count * 3);
  s.indices.reserve(count * 3);
  for (size_t i = 0; i < count; ++i) {
    const double cx = u01(rng) * size, cy = u01(rng) * size;
    const double rot = u01(rng) * 6.283185307179586;
    const double z = u01(rng) * 1.8 - 0.9;
    const double dz = (u01(rng) - 0.5) * 0.1;
    for (int k = 0; k < 3; ++k) {
      const double a = rot + k * 2.0943951023931953;
      const double x = cx + R * std::cos(a), y = cy + R * std::sin(a);
      s.positions.emplace_back(float(x / size * 2.0 - 1.0), float(y / size * 2.0 - 1.0), float(z + dz * k), 1.0f);
      s.indices.push_back(uint32_t(s.positions.size() - 1));
    }
  }
  return s;
}

}  // namespace bench
