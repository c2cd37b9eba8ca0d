// Mesh repairs and conversions: area-weighted normals, normal repair, winding flips, strips and fans, checks.
#include <limits>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scenes/mesh_ops.h"

namespace {

TEST(MeshOps, NormalsAreAreaWeighted) {
  // Vertex 0 is shared by a large triangle facing +Z and a small one facing +X.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}, {0, 1, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 3, 4};
  const auto n = scenes::compute_normals(p, idx);
  // Sum of (16/2 * 2) +Z and (1/2 * 2) +X: (1, 0, 16) normalised.
  const glm::vec3 expected = glm::normalize(glm::vec3(1, 0, 16));
  EXPECT_NEAR(glm::distance(n[0], expected), 0.0f, 1e-6f);
  EXPECT_EQ(n[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(n[3], glm::vec3(1, 0, 0));
}

// The same normals at any scale a float holds: at 1e10 the float sums' squares overflowed (normalize gave 0, the
// model lit black) and below 1e-6 they fell under the usable floor (every normal became +Y).
TEST(MeshOps, NormalsAtEveryScale) {
  const std::vector<glm::vec3> unit = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}, {0, 1, 0}};
  const std::vector<uint32_t> idx = {0, 1, 2, 0, 3, 4};
  const auto expected = scenes::compute_normals(unit, idx);
  for (const float scale : {1e-30f, 1e-10f, 1e-6f, 1e10f, 1e18f, 1e30f}) {
    std::vector<glm::vec3> p = unit;
    for (glm::vec3& v : p) v *= scale;
    const auto n = scenes::compute_normals(p, idx);
    for (size_t i = 0; i < n.size(); ++i)
      EXPECT_NEAR(glm::distance(n[i], expected[i]), 0.0f, 1e-6f) << "scale " << scale << ", vertex " << i;
  }
  // A given normal too long to normalize in float is replaced, not normalized to zero.
  scenes::Mesh m;
  m.positions = unit;
  m.indices = idx;
  m.normals = std::vector<glm::vec3>(unit.size(), glm::vec3(0, 0, 1));
  m.normals[1] = glm::vec3(1e30f, 0, 0);
  EXPECT_EQ(scenes::repair_normals(m), 1u);
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
}

TEST(MeshOps, UnusedVertexGetsUp) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  const auto n = scenes::compute_normals(p, std::vector<uint32_t>{0, 1, 2});
  EXPECT_EQ(n[3], glm::vec3(0, 1, 0));
}

TEST(MeshOps, RepairFillsMissingAndReplacesBadNormals) {
  scenes::Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  EXPECT_EQ(scenes::repair_normals(m), 0u);
  ASSERT_EQ(m.normals.size(), 3u);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  m.normals = {{0, 0, 1}, {nan, 0, 0}, {inf, 0, 0}};
  EXPECT_EQ(scenes::repair_normals(m), 2u);
  for (const auto& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(MeshOps, FlipWindingReversesTriangles) {
  scenes::Mesh m;
  m.indices = {0, 1, 2, 3, 4, 5};
  scenes::flip_winding(m);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1, 3, 5, 4}));
}

TEST(MeshOps, StripsAndFansFollowGltfOrderAndDropRestarts) {
  EXPECT_EQ(scenes::strip_to_list(std::vector<uint32_t>{0, 1, 2, 3, 4}),
            (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
  // A repeated index (restart padding) makes degenerate triangles, which are dropped.
  EXPECT_EQ(scenes::strip_to_list(std::vector<uint32_t>{0, 1, 2, 2, 5, 5, 6, 7}).size() % 3, 0u);
  EXPECT_EQ(scenes::strip_to_list(std::vector<uint32_t>{0, 1, 2, 2, 5}), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(scenes::fan_to_list(std::vector<uint32_t>{0, 1, 2, 3}), (std::vector<uint32_t>{1, 2, 0, 2, 3, 0}));
  EXPECT_TRUE(scenes::strip_to_list(std::vector<uint32_t>{0, 1}).empty());
  EXPECT_TRUE(scenes::fan_to_list(std::vector<uint32_t>{}).empty());
}

TEST(MeshOps, ProblemsAreNamed) {
  scenes::Mesh m;
  EXPECT_EQ(scenes::mesh_problem(m), "empty mesh (no triangles)");
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1};
  EXPECT_EQ(scenes::mesh_problem(m), "index count 2 is not a multiple of 3");
  m.indices = {0, 1, 3};
  EXPECT_EQ(scenes::mesh_problem(m), "index 2 is 3, out of range for 3 vertices");
  m.indices = {0, 1, 2};
  m.positions[1].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(scenes::mesh_problem(m), "vertex 1 has a non-finite position");
  m.positions[1].y = 0;
  m.texcoords = {{0, 0}};
  EXPECT_EQ(scenes::mesh_problem(m), "1 texture coordinates for 3 vertices");
  m.texcoords.clear();
  EXPECT_EQ(scenes::mesh_problem(m), std::nullopt);
}

}  // namespace
