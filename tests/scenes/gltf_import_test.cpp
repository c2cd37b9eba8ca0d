// glTF import on tiny files made by the test: strips, fans, non-indexed and 16-bit indexed primitives,
// mirrored nodes (winding flipped), missing and NaN normals, node hierarchies, cameras, KHR lights, materials,
// sparse accessors and GLB containers.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf_import.h"
#include "scenes/scene_build.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/scenes/scene_checks.h"
#include "tests/support.h"

namespace {

using testsupport::GltfFixture;

// A unit quad in the XY plane facing +Z, as 4 vertices.
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};

glm::vec3 triangle_normal(const scenes::Mesh& m, size_t t) {
  const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                  c = m.positions[m.indices[3 * t + 2]];
  return glm::normalize(glm::cross(b - a, c - a));
}

TEST(GltfImport, TriangleStripBecomesCounterClockwiseList) {
  const auto dir = testsupport::temp_dir("gltf_strip");
  GltfFixture f;
  f.node({{"mesh", f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 3}), 5)}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "strip"));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  for (size_t t = 0; t < 2; ++t) EXPECT_GT(triangle_normal(s.meshes[0], t).z, 0.99f);
}

TEST(GltfImport, NonIndexedStripAndFan) {
  const auto dir = testsupport::temp_dir("gltf_fan");
  GltfFixture f;
  // Fan around the origin: v1, v2, v3 counter-clockwise seen from +Z.
  const std::vector<glm::vec3> fan = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  f.node({{"mesh", f.mesh(f.positions(fan), -1, 6)}});
  f.node({{"mesh", f.mesh(f.positions(kQuad), -1, 5)}, {"translation", {3, 0, 0}}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "fan"));
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{1, 2, 0, 2, 3, 0}));
  EXPECT_EQ(s.meshes[1].indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  for (const auto& m : s.meshes)
    for (size_t t = 0; t < m.triangle_count(); ++t) EXPECT_GT(triangle_normal(m, t).z, 0.99f);
}

TEST(GltfImport, NonIndexedTrianglesAnd16BitIndices) {
  const auto dir = testsupport::temp_dir("gltf_nonindexed");
  GltfFixture f;
  const std::vector<glm::vec3> six = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}};
  f.node({{"mesh", f.mesh(f.positions(six))}});
  f.node({{"mesh", f.mesh(f.positions(kQuad), f.indices16({0, 1, 2, 2, 1, 3}))}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "nonindexed"));
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(s.meshes[1].indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  EXPECT_EQ(scenes::triangle_count(s), 4u);
}

TEST(GltfImport, MirroredNodesGetFlippedWinding) {
  const auto dir = testsupport::temp_dir("gltf_mirror");
  GltfFixture f;
  const int mesh = f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}));
  f.node({{"mesh", mesh}});
  f.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}, {"translation", {-2, 0, 0}}});
  f.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 5, 1}}});  // mirror in z
  // Two mirrors cancel: parent scale -1 in x, child scale -1 in y.
  const int child = f.node({{"mesh", mesh}, {"scale", {1, -1, 1}}}, false);
  f.node({{"children", {child}}, {"scale", {-1, 1, 1}}, {"translation", {0, 4, 0}}});
  const scenes::Scene s = scenes::load_scene(f.write_gltf(dir, "mirror"));
  ASSERT_EQ(s.instances.size(), 4u);
  EXPECT_EQ(s.instances[0].mesh, s.instances[3].mesh) << "an even number of mirrors keeps the mesh";
  EXPECT_NE(s.instances[0].mesh, s.instances[1].mesh);
  EXPECT_EQ(s.instances[1].mesh, s.instances[2].mesh) << "one flipped copy serves every mirrored instance";
  EXPECT_EQ(testsupport::winding_agreement(s), 1.0);
  // Mirrored in x, the quad still faces +Z: its world-space triangles stay counter-clockwise seen from +Z.
  const scenes::TriangleSoup soup = scenes::flatten_instances(s, std::vector<uint32_t>{1});
  for (size_t t = 0; t < soup.triangle_count(); ++t) {
    const glm::vec3 a = soup.positions[soup.indices[3 * t]], b = soup.positions[soup.indices[3 * t + 1]],
                    c = soup.positions[soup.indices[3 * t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
  }
}

TEST(GltfImport, MissingNormalsAreComputedAndNanNormalsReplaced) {
  const auto dir = testsupport::temp_dir("gltf_normals");
  GltfFixture f;
  f.node({{"mesh", f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}))}});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<glm::vec3> normals = {{0, 0, 1}, {nan, nan, nan}, {0, 0, 0}, {0, 0, 1}};
  f.node({{"mesh", f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}), 4, f.normals(normals))}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "normals"));
  ASSERT_EQ(s.meshes.size(), 2u);
  for (const auto& m : s.meshes)
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("NORMAL: 2 non-finite or zero normals replaced"), std::string::npos) << s.warnings[0];
}

TEST(GltfImport, NodeHierarchyComposesTrsAndMatrices) {
  const auto dir = testsupport::temp_dir("gltf_hierarchy");
  GltfFixture f;
  const int mesh = f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}));
  const float h = std::sqrt(0.5f);
  const int child = f.node({{"mesh", mesh}, {"rotation", {0, h, 0, h}}, {"scale", {2, 2, 2}}}, false);
  f.node({{"children", {child}}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1}}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "hierarchy"));
  ASSERT_EQ(s.instances.size(), 1u);
  glm::mat4 expected = glm::translate(glm::mat4(1.0f), {10, 20, 30});
  expected = glm::rotate(expected, glm::radians(90.0f), {0, 1, 0});
  expected = glm::scale(expected, {2, 2, 2});
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(s.instances[0].transform[c][r], expected[c][r], 1e-5f);
}

TEST(GltfImport, CamerasLightsAndMaterials) {
  const auto dir = testsupport::temp_dir("gltf_extras");
  GltfFixture f;
  const int mesh = f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}));
  f.doc["meshes"][mesh]["primitives"][0]["material"] = 0;
  f.doc["materials"] = {{{"name", "paint"},
                         {"doubleSided", true},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}}, {"baseColorTexture", {{"index", 0}}},
                           {"roughnessFactor", 0.5}}}}};
  f.doc["textures"] = {{{"source", 0}}};
  f.doc["images"] = {{{"uri", "tex%20a.png"}}};
  f.doc["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 1.5}}}}};
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 7}, {"range", 9},
       {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}}};
  f.node({{"mesh", mesh}});
  f.node({{"camera", 0}, {"translation", {0, 1, 5}}});
  // Rotated -90° about X: the light's -Z points down.
  const float h = std::sqrt(0.5f);
  f.node({{"translation", {0, 3, 0}}, {"rotation", {-h, 0, 0, h}},
          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "extras"));

  ASSERT_EQ(s.materials.size(), 1u);
  const scenes::Material& m = s.materials[0];
  EXPECT_EQ(m.name, "paint");
  EXPECT_EQ(m.base_color, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_EQ(m.texture, (dir / "tex a.png").lexically_normal().generic_string());
  EXPECT_TRUE(m.double_sided);
  EXPECT_FLOAT_EQ(m.shininess, 30.0f);  // 2 / 0.5^4 - 2
  EXPECT_FLOAT_EQ(m.specular_strength, 0.15f);

  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].position, glm::vec3(0, 1, 5));
  EXPECT_EQ(s.cameras[0].target, glm::vec3(0, 1, 4));
  const auto& p = std::get<scenes::Perspective>(s.cameras[0].projection);
  EXPECT_NEAR(p.fovy_deg, glm::degrees(0.5f), 1e-4f);
  EXPECT_EQ(p.aspect, 1.5f);
  EXPECT_FLOAT_EQ(p.far, 100.0f);  // no zfar: 1000 * znear

  ASSERT_EQ(s.lights.size(), 1u);
  const scenes::Light& l = s.lights[0];
  EXPECT_EQ(l.type, scenes::LightType::spot);
  EXPECT_NEAR(glm::distance(l.direction, glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(l.position, glm::vec3(0, 3, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(l.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_EQ(l.intensity, 7.0f);
  EXPECT_EQ(l.range, 9.0f);
  EXPECT_NEAR(l.inner_cone_deg, glm::degrees(0.25f), 1e-4f);
  EXPECT_NEAR(l.outer_cone_deg, glm::degrees(0.5f), 1e-4f);
  EXPECT_EQ(l.shadow.technique, scenes::ShadowTechnique::shadowmap);
}

TEST(GltfImport, SparseAccessorSubstitutesValues) {
  const auto dir = testsupport::temp_dir("gltf_sparse");
  GltfFixture f;
  const int pos = f.positions(kQuad);
  const std::vector<uint32_t> which = {3};
  const std::vector<glm::vec3> values = {{5, 5, 0}};
  const int idx = f.indices(which), val = f.positions(values);
  const auto& accessors = f.doc["accessors"];
  f.doc["accessors"][pos]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", accessors[idx]["bufferView"]}, {"componentType", 5125}}},
      {"values", {{"bufferView", accessors[val]["bufferView"]}}}};
  f.node({{"mesh", f.mesh(pos, f.indices({0, 1, 2, 2, 1, 3}))}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "sparse"));
  EXPECT_EQ(s.meshes[0].positions[3], glm::vec3(5, 5, 0));
  EXPECT_EQ(s.meshes[0].positions[2], glm::vec3(0, 1, 0));
}

TEST(GltfImport, GlbAndGltfGiveTheSameScene) {
  const auto dir = testsupport::temp_dir("gltf_glb");
  GltfFixture f;
  f.node({{"mesh", f.mesh(f.positions(kQuad), f.indices({0, 1, 2, 2, 1, 3}))}, {"translation", {1, 2, 3}}});
  scenes::Scene a = scenes::load_scene(f.write_gltf(dir, "model"));
  scenes::Scene b = scenes::load_scene(f.write_glb(dir, "model"));
  EXPECT_EQ(a.meshes, b.meshes);
  EXPECT_EQ(a.instances, b.instances);
  EXPECT_EQ(a.cameras, b.cameras) << "both framed by the default camera";
}

}  // namespace

// Issue 23: a chain of 10,000 nested nodes (each translated by 1 mm) overflowed the call stack; it now imports,
// with the transforms composed down the whole chain.
TEST(GltfImport, ADeepChainOfNodesImports) {
  const auto dir = testsupport::temp_dir("gltf_deep_chain");
  testsupport::GltfFixture f;
  const int m = f.mesh(f.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  constexpr int kDepth = 10000;
  for (int i = 0; i < kDepth; ++i) {
    nlohmann::json node = {{"translation", {0.001, 0, 0}}};
    if (i + 1 < kDepth) node["children"] = {i + 1};
    else node["mesh"] = m;
    f.node(node, i == 0);
  }
  const scenes::Scene s = scenes::load_scene(f.write_gltf(dir, "chain"));
  ASSERT_EQ(s.instances.size(), 1u);
  EXPECT_NEAR(s.instances[0].transform[3].x, 10.0f, 1e-3f);
}
