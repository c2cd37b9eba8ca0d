// Texels per steradian over a hemisphere for each omnidirectional technique at equal memory (6 · 512² texels:
// the cube's six 512² faces, the pyramid's 1254² square, a hemispherical light's single 1254² paraboloid, and
// a point light's two 887² paraboloids). Each texel's solid angle is that of the spherical quad through its
// corners' directions; only texels whose centre lies in the hemisphere (and, for the paraboloid, inside its
// disc) count. The minimum, maximum and their ratio are printed (docs/omnidirectional.md quotes them) and
// checked against the closed forms where there is one: the cube's ratio is 3^(3/2), the paraboloid's 4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/geometric.hpp>

#include "shading/cube_face.h"

namespace {

double tri_solid_angle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  a = glm::normalize(a), b = glm::normalize(b), c = glm::normalize(c);
  return 2.0 * std::atan2(std::fabs(glm::dot(a, glm::cross(b, c))), 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

struct Density {
  double min = 1e300, max = 0.0, used_sr = 0.0;
  long texels = 0;
};

// dir(u, v) maps face coordinates in [0, 1]² to a direction (the hemisphere is z > 0); `valid` rejects unused
// texels.
void accumulate(Density& d, int n, const std::function<glm::dvec3(double, double)>& dir,
                const std::function<bool(double, double)>& valid) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u0 = double(i) / n, u1 = double(i + 1) / n, v0 = double(j) / n, v1 = double(j + 1) / n;
      const double uc = (i + 0.5) / n, vc = (j + 0.5) / n;
      if (!valid(uc, vc) || !(dir(uc, vc).z > 0.0)) continue;
      const glm::dvec3 a = dir(u0, v0), b = dir(u1, v0), c = dir(u1, v1), e = dir(u0, v1);
      const double omega = tri_solid_angle(a, b, c) + tri_solid_angle(a, c, e);
      const double texels_per_sr = 1.0 / omega;
      d.min = std::min(d.min, texels_per_sr);
      d.max = std::max(d.max, texels_per_sr);
      d.used_sr += omega;
      ++d.texels;
    }
}

void report(const char* name, const Density& d) {
  std::printf("texels/sr %-22s min %9.0f  max %9.0f  ratio %.3f  (%ld texels cover %.3f sr)\n", name, d.min, d.max,
              d.max / d.min, d.texels, d.used_sr);
}

auto always = [](double, double) { return true; };

TEST(OmniDensity, TexelsPerSteradianAtEqualMemory) {
  // Cube, 512² per face; the hemisphere z > 0 (the light facing +z): +Z whole, the four side faces half.
  Density cube;
  for (int f = 0; f < 6; ++f) {
    const shading::CubeFaceAxes& a = shading::kCubeFaceAxes[f];
    accumulate(
        cube, 512,
        [&](double u, double v) {
          return glm::dvec3(a.major) + (2 * u - 1) * glm::dvec3(a.s_axis) + (2 * v - 1) * glm::dvec3(a.t_axis);
        },
        always);
  }
  report("cube 6x512^2", cube);
  EXPECT_NEAR(cube.used_sr, 2.0 * M_PI, 0.02);
  EXPECT_NEAR(cube.max / cube.min, std::pow(3.0, 1.5), 0.05);

  // Paraboloid: (x, y) = 2 (u, v) − 1 → p = (2x, 2y, 1 − x² − y²) / (1 + x² + y²); the disc x² + y² <= 1.
  auto para_dir = [](double u, double v) {
    const double x = 2 * u - 1, y = 2 * v - 1, r2 = x * x + y * y;
    return glm::dvec3(2 * x, 2 * y, 1 - r2) / (1 + r2);
  };
  auto in_disc = [](double u, double v) { return (2 * u - 1) * (2 * u - 1) + (2 * v - 1) * (2 * v - 1) <= 1.0; };
  Density para1, para2;
  accumulate(para1, 1254, para_dir, in_disc);
  accumulate(para2, 887, para_dir, in_disc);
  report("paraboloid 1x1254^2", para1);
  report("paraboloid 2x887^2", para2);
  EXPECT_NEAR(para1.max / para1.min, 4.0, 0.05);
  EXPECT_NEAR(para1.used_sr, 2.0 * M_PI, 0.02);

  // Pyramid: (s, t) − 0.5 = (x, y) / (2 (max(|x|, |y|) + z)); with max + z = 1: x = 2 ds, y = 2 dt,
  // z = 1 − max(|x|, |y|).
  auto pyr_dir = [](double u, double v) {
    const double x = 2 * (u - 0.5), y = 2 * (v - 0.5);
    return glm::dvec3(x, y, 1.0 - std::max(std::fabs(x), std::fabs(y)));
  };
  Density pyr;
  accumulate(pyr, 1254, pyr_dir, always);
  report("pyramid 1254^2", pyr);
  EXPECT_NEAR(pyr.used_sr, 2.0 * M_PI, 0.02);
  EXPECT_GT(pyr.min, cube.min);  // the point of the technique: more texels everywhere at equal memory
}

}  // namespace
