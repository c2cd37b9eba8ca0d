// Scene queries: exact world-space bounds, triangle counts with filters, world-space triangle soup.
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera_math.h"
#include "scenes/primitives.h"
#include "scenes/scene_queries.h"

namespace {

scenes::Scene two_boxes() {
  scenes::Scene s;
  s.meshes.push_back(scenes::make_shape_mesh(scenes::BoxShape{{2, 2, 2}}));
  s.materials.push_back(scenes::Material{});
  scenes::Instance a;
  a.transform = glm::translate(glm::mat4(1.0f), {10, 0, 0});
  a.object = 0;
  scenes::Instance b;
  b.transform = glm::rotate(glm::scale(glm::mat4(1.0f), {1, 3, 1}), glm::radians(45.0f), {0, 1, 0});
  b.casts_shadows = false;
  b.object = 1;
  s.instances = {a, b};
  s.objects = {"a", "b"};
  return s;
}

TEST(SceneQueries, BoundsAreExact) {
  const scenes::Scene s = two_boxes();
  const scenes::Aabb a = scenes::instance_bounds(s, 0);
  EXPECT_EQ(a.min, glm::vec3(9, -1, -1));
  EXPECT_EQ(a.max, glm::vec3(11, 1, 1));
  const scenes::Aabb b = scenes::object_bounds(s, 1);
  EXPECT_NEAR(b.max.x, std::sqrt(2.0f), 1e-5f);  // a 45° turned unit-half box reaches sqrt(2)
  EXPECT_NEAR(b.max.y, 3.0f, 1e-6f);
  const scenes::Aabb all = scenes::scene_bounds(s);
  EXPECT_NEAR(all.min.x, -std::sqrt(2.0f), 1e-5f);
  EXPECT_EQ(all.max.x, 11.0f);
  EXPECT_EQ(scenes::scene_bounds(s, scenes::InstanceFilter::casters), a);
  EXPECT_TRUE(scenes::Aabb{}.empty());
  EXPECT_FALSE(all.empty());
}

TEST(SceneQueries, CountsAndSoup) {
  const scenes::Scene s = two_boxes();
  EXPECT_EQ(scenes::triangle_count(s), 24u);
  EXPECT_EQ(scenes::triangle_count(s, scenes::InstanceFilter::casters), 12u);
  EXPECT_EQ(scenes::triangle_count(s, scenes::InstanceFilter::receivers), 24u);
  const scenes::TriangleSoup soup = scenes::flatten(s, scenes::InstanceFilter::casters);
  EXPECT_EQ(soup.triangle_count(), 12u);
  EXPECT_EQ(soup.positions.size(), s.meshes[0].positions.size());
  for (const glm::vec3& p : soup.positions) EXPECT_TRUE(p.x == 9.0f || p.x == 11.0f);
  const scenes::TriangleSoup both = scenes::flatten(s);
  EXPECT_EQ(both.triangle_count(), 24u);
  for (uint32_t i : both.indices) EXPECT_LT(i, both.positions.size());
  EXPECT_EQ(scenes::object_instances(s, 1), (std::vector<uint32_t>{1}));
}

TEST(SceneQueries, FrameCameraSeesTheBox) {
  scenes::Aabb box;
  box.extend(glm::vec3(-3, 0, -1));
  box.extend(glm::vec3(5, 2, 7));
  const scenes::Camera c = scenes::frame_camera(box);
  const glm::mat4 vp = scenes::projection_matrix(c, 1.0f) * scenes::view_matrix(c);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z);
    const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k] / clip.w), 1.0f) << corner;
  }
}

}  // namespace
