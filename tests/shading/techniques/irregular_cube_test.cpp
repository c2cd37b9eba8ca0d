// The irregular z-buffer for point lights (shading/techniques/irregular_cube.h), per cube face: triangles near a
// point light over a floor and under a ceiling, every sample's answer known in closed form, with samples on every
// face and on the triangles' edges and corners; the face each sample goes to. Whole frames (against the ray-cast
// reference, at any thread count) are irregular_test.cpp's, with a point light among the others.
#include <gtest/gtest.h>

#include <vector>

#include "shading/cube_face.h"
#include "shading/techniques/irregular_cube.h"
#include "tests/support.h"

namespace {

namespace tech = shading::tech;

bool in_closed_triangle(double x, double z) { return x >= 0.0 && z >= 0.0 && x + z <= 1.0; }
bool on_boundary(double x, double z) {
  return in_closed_triangle(x, z) && (x == 0.0 || z == 0.0 || x + z == 1.0);
}

// The light at (0.25, 0.5, 0.25), half a metre over the floor, and the triangle (0, ¼, 0), (1, ¼, 0), (0, ¼, 1)
// halfway between, with its mirror image above the light halfway to a ceiling at y = 1: a floor point (x, 0, z)
// is shadowed when its segment to the light meets y = ¼ at ((0.25 + x) / 2, (0.25 + z) / 2) inside the closed
// triangle, a ceiling point (x, 1, z) by the same rule at y = ¾. Samples every 1/16 m over [−1.5, 2]² on both:
// those farther than half a metre across from the light go to the side faces, the others to −Y or +Y. A face's
// projection used for another face's samples (those behind its plane) misses triangles, and this test fails.
TEST(IrregularCube, OneTriangleNearAPointLightAgreesExactlyOnEveryFace) {
  const glm::vec3 light(0.25f, 0.5f, 0.25f);
  // The same triangle mirrored above the light (y = ¾) over a ceiling (y = 1): a ceiling point is shadowed by the
  // same rule. Its samples lie behind the floor's faces: a face's projection used for them would miss it.
  const std::vector<glm::vec3> positions{{0.0f, 0.25f, 0.0f}, {1.0f, 0.25f, 0.0f}, {0.0f, 0.25f, 1.0f},
                                         {0.0f, 0.75f, 0.0f}, {1.0f, 0.75f, 0.0f}, {0.0f, 0.75f, 1.0f}};
  const std::vector<uint32_t> indices{0, 1, 2, 3, 4, 5};
  std::vector<glm::vec3> samples;
  for (float y : {0.0f, 1.0f})
    for (int i = -24; i <= 32; ++i)
      for (int k = -24; k <= 32; ++k) samples.emplace_back(float(i) / 16.0f, y, float(k) / 16.0f);
  samples.emplace_back(0.25f, 0.25f, 0.25f);  // in the triangle itself: it never shadows itself
  samples.emplace_back(0.25f, 0.4f, 0.25f);   // between the triangle and the light
  samples.emplace_back(1.0f, 0.5f, 1.0f);     // level with the light, beside it: nothing between
  int faces[6] = {};
  for (const glm::vec3& s : samples) ++faces[tech::irregular_cube_face_of(light, s)];
  for (int f : {0, 1, 2, 3, 4, 5}) EXPECT_GT(faces[f], 0) << "no sample on face " << f;
  std::vector<uint8_t> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::ThreadPool pool(threads);
    tech::GridStats stats;
    const std::vector<uint8_t> shadowed =
        tech::irregular_cube_shadow(light, samples, {positions, indices}, tech::GridSettings{}, pool, stats);
    ASSERT_EQ(shadowed.size(), samples.size());
    size_t edges = 0, dark = 0;
    for (size_t i = 0; i + 3 < samples.size(); ++i) {
      const double qx = (0.25 + samples[i].x) / 2.0, qz = (0.25 + samples[i].z) / 2.0;
      EXPECT_EQ(bool(shadowed[i]), in_closed_triangle(qx, qz)) << "sample at x " << samples[i].x << ", z "
                                                               << samples[i].z << ", " << threads << " threads";
      edges += on_boundary(qx, qz), dark += shadowed[i];
    }
    EXPECT_GT(edges, 80u);
    EXPECT_GT(dark, 1000u);
    EXPECT_FALSE(shadowed[samples.size() - 3]);
    EXPECT_FALSE(shadowed[samples.size() - 2]);
    EXPECT_FALSE(shadowed[samples.size() - 1]);
    EXPECT_EQ(stats.samples, samples.size());
    if (threads == 0) first = shadowed;
    EXPECT_EQ(shadowed, first) << threads << " threads";
  }
}

// Each face's projection looks along its major axis with s and t across, as the cube map's faces do.
TEST(IrregularCube, FacesFollowGlsMajorAxisTable) {
  const glm::vec3 light(1.0f, 2.0f, 3.0f);
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(5.0f, 1.0f, -2.0f)), 0);
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(-5.0f, 1.0f, -2.0f)), 1);
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(0.5f, 3.0f, -2.0f)), 2);
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(0.5f, -3.0f, -2.0f)), 3);
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(1.0f, 1.0f, 1.0f)), 4);  // ties prefer z
  EXPECT_EQ(tech::irregular_cube_face_of(light, light + glm::vec3(1.0f, -1.0f, -1.0f)), 5);
  for (int f = 0; f < 6; ++f) {
    const tech::IrregularLight l = tech::irregular_cube_face(light, f);
    EXPECT_TRUE(l.spot);
    EXPECT_EQ(l.axis, glm::dvec3(shading::kCubeFaceAxes[f].major));
    EXPECT_EQ(l.position, glm::dvec3(light));
  }
}

}  // namespace
