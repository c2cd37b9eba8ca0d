// Built-in primitives: valid meshes with outward, counter-clockwise faces (signed volume against the analytic
// one for closed solids), terrain on its height function, and parameter checks.
#include <numbers>

#include <gtest/gtest.h>

#include "scenes/mesh_ops.h"
#include "scenes/primitives.h"
#include "tests/scenes/scene_checks.h"

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Volume enclosed by a closed mesh, positive when its faces point outwards (divergence theorem).
double signed_volume(const scenes::Mesh& m) {
  double v = 0.0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]), c(m.positions[m.indices[t + 2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

scenes::Scene scene_of(const scenes::Mesh& m) {
  scenes::Scene s;
  s.meshes.push_back(m);
  s.instances.push_back(scenes::Instance{});
  return s;
}

void expect_valid(const scenes::Mesh& m) {
  EXPECT_EQ(scenes::mesh_problem(m), std::nullopt) << m.name;
  ASSERT_EQ(m.normals.size(), m.positions.size());
  ASSERT_EQ(m.texcoords.size(), m.positions.size());
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << m.name;
  EXPECT_GT(testsupport::winding_agreement(scene_of(m)), 0.999) << m.name;
}

TEST(Primitives, ClosedSolidsEncloseTheirVolumeOutwards) {
  struct Case {
    scenes::Shape shape;
    double volume;
    double tolerance;  // relative: tessellated curves enclose a little less
  };
  const scenes::RoomShape room{{4, 3, 5}, 0.5f, scenes::room_floor | scenes::room_neg_x | scenes::room_pos_z};
  const double room_volume = 5.0 * 0.5 * 6.0 + 0.5 * 3 * 5 + 5.0 * 3 * 0.5;
  const Case cases[] = {
      {scenes::BoxShape{{1, 2, 3}}, 6.0, 1e-6},
      {scenes::SphereShape{2.0f, 64, 32}, 4.0 / 3.0 * kPi * 8.0, 0.01},
      {scenes::CylinderShape{1.0f, 3.0f, 64, true}, kPi * 3.0, 0.01},
      {scenes::ConeShape{1.0f, 3.0f, 64, true}, kPi * 1.0, 0.01},
      {room, room_volume, 1e-6},
  };
  for (const Case& c : cases) {
    const scenes::Mesh m = scenes::make_shape_mesh(c.shape);
    EXPECT_EQ(m.name, scenes::shape_name(c.shape));
    expect_valid(m);
    EXPECT_NEAR(signed_volume(m), c.volume, c.volume * c.tolerance) << m.name;
  }
}

TEST(Primitives, PlaneFacesUp) {
  const scenes::Mesh m = scenes::make_shape_mesh(scenes::PlaneShape{{4, 2}, 3});
  expect_valid(m);
  EXPECT_EQ(m.triangle_count(), 18u);
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  }
}

TEST(Primitives, TerrainLiesOnItsHeightFunction) {
  const scenes::TerrainShape t{{20, 10}, 32, 0.7f, 5.0f, 3};
  const scenes::Mesh m = scenes::make_shape_mesh(t);
  expect_valid(m);
  float lo = 1e9f, hi = -1e9f;
  for (const glm::vec3& p : m.positions) {
    EXPECT_FLOAT_EQ(p.y, scenes::terrain_height(t, p.x, p.z));
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  EXPECT_LE(hi, 0.7f);
  EXPECT_GE(lo, -0.7f);
  EXPECT_GT(hi - lo, 0.3f) << "uneven";
  scenes::TerrainShape other = t;
  other.seed = 4;
  EXPECT_NE(scenes::terrain_height(t, 1.0f, 2.0f), scenes::terrain_height(other, 1.0f, 2.0f));
}

TEST(Primitives, BadParametersAreNamed) {
  EXPECT_EQ(scenes::check_shape(scenes::SphereShape{-1.0f}), "radius: must be positive");
  EXPECT_EQ(scenes::check_shape(scenes::SphereShape{1.0f, 2}), "segments: must be between 3 and 4096");
  EXPECT_EQ(scenes::check_shape(scenes::BoxShape{{1, 0, 1}}), "size: must be positive");
  EXPECT_EQ(scenes::check_shape(scenes::RoomShape{{1, 1, 1}, 0.1f, 0}), "sides: must name at least one side");
  EXPECT_EQ(scenes::check_shape(scenes::TerrainShape{{1, 1}, 8, -1.0f}), "amplitude: must not be negative");
  EXPECT_EQ(scenes::check_shape(scenes::CylinderShape{}), std::nullopt);
}

}  // namespace
