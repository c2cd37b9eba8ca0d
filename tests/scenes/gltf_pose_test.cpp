// The default pose of glTF meshes (scenes/gltf_pose.h) on files made by the test, with answers worked by hand:
// a two-joint skin (the skinned node's own transform ignored, weights normalized, normals turned), morph targets
// at the node's and the mesh's default weights, KHR_mesh_quantization attributes, and the errors of each.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf_import.h"
#include "scenes/scene_error.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

using testsupport::GltfFixture;

// World positions of an instance's vertices.
std::vector<glm::vec3> world_positions(const scenes::Scene& s, size_t instance) {
  const scenes::Instance& inst = s.instances.at(instance);
  std::vector<glm::vec3> out;
  for (const glm::vec3& p : s.meshes.at(inst.mesh).positions) out.push_back(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
  return out;
}

void expect_near(const glm::vec3& got, const glm::vec3& want, const std::string& what) {
  EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
  EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
  EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

std::string error_of(const std::filesystem::path& file) {
  try {
    scenes::import_gltf(file);
  } catch (const scenes::SceneError& e) {
    return e.what();
  }
  return "";
}

// Joint 0 at (10, 0, 0); joint 1 its child one metre up, turned 90° about Z; bound where joint 1 stood at
// (0, 1, 0) unturned and joint 0 at the origin. The skinned node is moved by (100, 0, 0), which glTF says to
// ignore. Vertices: (0, 0, 0) on joint 0 → (10, 0, 0); (0, 2, 0) on joint 1 → T(10,1,0)·Rz(90°)·(0, 1, 0) =
// (9, 1, 0); (1, 0, 0) half on each (weights 0.25 + 0.25, divided by their sum) → ((11, 0, 0) + (11, 2, 0)) / 2
// = (11, 1, 0); (0, 1, 0) on joint 1 → (10, 1, 0).
struct SkinFile {
  GltfFixture f;
  int mesh = -1, joints_accessor = -1, weights_accessor = -1;
  SkinFile() {
    const std::vector<glm::vec3> pos = {{0, 0, 0}, {0, 2, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<glm::vec3> nrm = {{1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    const std::vector<uint8_t> joints = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    const std::vector<float> weights = {1, 0, 0, 0, 1, 0, 0, 0, 0.25f, 0.25f, 0, 0, 1, 0, 0, 0};
    mesh = f.mesh(f.positions(pos), f.indices({0, 2, 3, 0, 3, 1}), 4, f.normals(nrm));
    joints_accessor = f.accessor(joints.data(), joints.size(), 5121, 4, "VEC4");
    weights_accessor = f.accessor(weights.data(), weights.size() * 4, 5126, 4, "VEC4");
    auto& attributes = f.doc["meshes"][mesh]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = joints_accessor;
    attributes["WEIGHTS_0"] = weights_accessor;
    const glm::mat4 inverse_bind[2] = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -1, 0))};
    const int ibm = f.accessor(inverse_bind, sizeof inverse_bind, 5126, 2, "MAT4");
    const float s = std::sqrt(0.5f);
    const int j1 = f.node({{"name", "j1"}, {"translation", {0, 1, 0}}, {"rotation", {0, 0, s, s}}}, false);
    const int j0 = f.node({{"name", "j0"}, {"translation", {10, 0, 0}}, {"children", {j1}}});
    f.doc["skins"] = nlohmann::json::array({{{"joints", {j0, j1}}, {"inverseBindMatrices", ibm}}});
    f.node({{"name", "skinned"}, {"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}});
  }
};

TEST(GltfPose, SkinPlacesVerticesByTheirJoints) {
  const auto dir = testsupport::temp_dir("gltf_pose_skin");
  SkinFile file;
  const scenes::Scene s = scenes::import_gltf(file.f.write_gltf(dir, "skin"));
  ASSERT_EQ(s.instances.size(), 1u);
  EXPECT_EQ(s.instances[0].transform, glm::mat4(1.0f));  // the skinned node's own transform is ignored
  const std::vector<glm::vec3> p = world_positions(s, 0);
  expect_near(p[0], {10, 0, 0}, "vertex 0 on joint 0");
  expect_near(p[1], {9, 1, 0}, "vertex 1 on joint 1");
  expect_near(p[2], {11, 1, 0}, "vertex 2 half on each");
  expect_near(p[3], {10, 1, 0}, "vertex 3 on joint 1");
  const scenes::Mesh& m = s.meshes[s.instances[0].mesh];
  expect_near(glm::normalize(m.normals[0]), {1, 0, 0}, "normal on joint 0");
  expect_near(glm::normalize(m.normals[1]), {0, 1, 0}, "normal turned with joint 1");
  EXPECT_TRUE(s.warnings.empty());

  // The same file with the joint turned back: the bind pose, where the skin moves nothing but by joint 0.
  file.f.doc["nodes"][0]["rotation"] = {0, 0, 0, 1};
  const scenes::Scene rest = scenes::import_gltf(file.f.write_gltf(dir, "rest"));
  expect_near(world_positions(rest, 0)[1], {10, 2, 0}, "vertex 1 in the bind pose");
}

TEST(GltfPose, SkinErrorsNameTheKey) {
  const auto dir = testsupport::temp_dir("gltf_pose_skin_errors");
  {
    SkinFile file;
    const std::vector<uint8_t> bad = {0, 0, 0, 0, 7, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    file.f.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = file.f.accessor(bad.data(), 16, 5121, 4, "VEC4");
    const auto path = file.f.write_gltf(dir, "joint");
    EXPECT_EQ(error_of(path), path.string() + ": meshes[0].primitives[0].attributes.JOINTS_0: vertex 1 names joint 7 "
                                              "of a skin with 2");
  }
  {
    SkinFile file;
    file.f.doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
    const auto path = file.f.write_gltf(dir, "weights");
    EXPECT_EQ(error_of(path),
              path.string() + ": meshes[0].primitives[0].attributes.WEIGHTS_0: missing: the primitive has JOINTS_0");
  }
  {
    SkinFile file;
    file.f.doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
    file.f.doc["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
    const auto path = file.f.write_gltf(dir, "nojoints");
    EXPECT_EQ(error_of(path), path.string() + ": meshes[0].primitives[0].attributes.JOINTS_0: missing: the node has a skin");
  }
  {
    SkinFile file;
    file.f.doc["skins"][0]["joints"] = {1};  // one joint, two inverse bind matrices: allowed; vertex 1 names joint 1
    const auto path = file.f.write_gltf(dir, "few");
    EXPECT_EQ(error_of(path), path.string() + ": meshes[0].primitives[0].attributes.JOINTS_0: vertex 1 names joint 1 "
                                              "of a skin with 1");
  }
  {
    SkinFile file;
    const glm::mat4 bad[2] = {glm::mat4(1.0f), glm::mat4(std::numeric_limits<float>::quiet_NaN())};
    file.f.doc["skins"][0]["inverseBindMatrices"] = file.f.accessor(bad, sizeof bad, 5126, 2, "MAT4");
    const auto path = file.f.write_gltf(dir, "nan");
    EXPECT_EQ(error_of(path), path.string() + ": skins[0].inverseBindMatrices: matrix 1 holds a value that is not a "
                                              "finite number");
  }
  {
    SkinFile file;  // a second set numbered 2: the gap would leave it unread
    file.f.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_2"] = file.joints_accessor;
    file.f.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_2"] = file.weights_accessor;
    const auto path = file.f.write_gltf(dir, "gap");
    EXPECT_EQ(error_of(path), path.string() + ": meshes[0].primitives[0].attributes.JOINTS_2: follows a gap: the sets "
                                              "of JOINTS_n are numbered from 0 without one (the last read is 0)");
  }
  {
    SkinFile file;  // a joint outside the scene's hierarchy is checked as a walked node is
    const int outside = file.f.node({{"rotation", {0, 0, 0, 0}}}, false);
    file.f.doc["skins"][0]["joints"] = {outside, 0};
    const auto path = file.f.write_gltf(dir, "outside");
    EXPECT_EQ(error_of(path), path.string() + ": nodes[" + std::to_string(outside) +
                                  "].rotation: is not a unit quaternion (its length is 0.000000)");
  }
  {
    SkinFile file;
    file.f.doc["nodes"][2]["skin"] = 3;
    const auto path = file.f.write_gltf(dir, "skin");
    EXPECT_EQ(error_of(path),
              path.string() + ": nodes[2].skin: index 3 is past the end of skins (the file has 1 entry)");
  }
}

// A mirroring node's skinned mesh is posed in world space under an identity instance: its winding is flipped by
// the importer (glTF §3.7.4: the node's global transform decides), its positions still the joints'.
TEST(GltfPose, AMirroredSkinnedNodeFlipsItsWinding) {
  const auto dir = testsupport::temp_dir("gltf_pose_mirror");
  SkinFile file;
  const scenes::Scene plain = scenes::import_gltf(file.f.write_gltf(dir, "plain"));
  file.f.doc["nodes"][2]["scale"] = {-1, 1, 1};
  const scenes::Scene mirrored = scenes::import_gltf(file.f.write_gltf(dir, "mirrored"));
  const scenes::Mesh &a = plain.meshes[plain.instances[0].mesh], &b = mirrored.meshes[mirrored.instances[0].mesh];
  ASSERT_EQ(a.indices.size(), b.indices.size());
  for (size_t t = 0; t < a.indices.size(); t += 3) {
    EXPECT_EQ(b.indices[t], a.indices[t]);
    EXPECT_EQ(b.indices[t + 1], a.indices[t + 2]);
    EXPECT_EQ(b.indices[t + 2], a.indices[t + 1]);
  }
  for (size_t v = 0; v < a.positions.size(); ++v) expect_near(b.positions[v], a.positions[v], "the joints place it");
}

// Weights of 0 everywhere leave a vertex where its node puts it, said once.
TEST(GltfPose, UnweightedVerticesArePlacedByTheNode) {
  const auto dir = testsupport::temp_dir("gltf_pose_unweighted");
  SkinFile file;
  const std::vector<float> weights = {1, 0, 0, 0, 0, 0, 0, 0, 0.25f, 0.25f, 0, 0, 1, 0, 0, 0};
  file.f.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] =
      file.f.accessor(weights.data(), weights.size() * 4, 5126, 4, "VEC4");
  const auto path = file.f.write_gltf(dir, "unweighted");
  const scenes::Scene s = scenes::import_gltf(path);
  expect_near(world_positions(s, 0)[1], {100, 2, 0}, "vertex 1, weights 0: the node's (100, 0, 0) moves it");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0], path.string() + ": nodes[2]: 1 skinned vertices have weights summing to 0: placed by the "
                                           "node's transform");
}

// One mesh with a target moving every vertex by (0, 0, 2): the node's weights (1) win over the mesh's (0.5), a
// node without weights takes the mesh's, and a mesh whose weights are all 0 is the plain shared mesh.
TEST(GltfPose, MorphTargetsAtTheirDefaultWeights) {
  const auto dir = testsupport::temp_dir("gltf_pose_morph");
  GltfFixture f;
  const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<glm::vec3> up(4, glm::vec3(0, 0, 2));
  const int mesh = f.mesh(f.positions(quad), f.indices({0, 1, 2, 2, 1, 3}));
  f.doc["meshes"][mesh]["primitives"][0]["targets"] = nlohmann::json::array({{{"POSITION", f.positions(up)}}});
  f.doc["meshes"][mesh]["weights"] = {0.5};
  f.node({{"mesh", mesh}, {"weights", {1.0}}});
  f.node({{"mesh", mesh}, {"translation", {5, 0, 0}}});
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "morph"));
  ASSERT_EQ(s.instances.size(), 2u);
  expect_near(world_positions(s, 0)[3], {1, 1, 2}, "node weights 1");
  expect_near(world_positions(s, 1)[3], {6, 1, 1}, "mesh weights 0.5, then the node's translation");

  f.doc["meshes"][mesh]["weights"] = {0.0};
  f.doc["nodes"][0].erase("weights");
  const scenes::Scene plain = scenes::import_gltf(f.write_gltf(dir, "plain"));
  ASSERT_EQ(plain.instances.size(), 2u);
  EXPECT_EQ(plain.instances[0].mesh, plain.instances[1].mesh);  // shared, as any unposed mesh
  expect_near(world_positions(plain, 0)[3], {1, 1, 0}, "weights 0");

  f.doc["nodes"][0]["weights"] = {1.0, 0.5};  // two weights for one target
  const auto counted = f.write_gltf(dir, "counted");
  EXPECT_EQ(error_of(counted), counted.string() + ": nodes[0].weights: 2 weights for 1 morph targets");
  f.doc["nodes"][0].erase("weights");

  f.doc["meshes"][mesh]["weights"] = {0.5};
  const std::vector<glm::vec3> few(3, glm::vec3(0, 0, 2));
  f.doc["meshes"][mesh]["primitives"][0]["targets"][0]["POSITION"] = f.positions(few);
  const auto path = f.write_gltf(dir, "short");
  EXPECT_EQ(error_of(path), path.string() + ": meshes[0].primitives[0].targets[0].POSITION: count 3 differs from "
                                            "POSITION's 4");
}

// KHR_mesh_quantization: positions as normalized SHORT are read where the file uses the extension, and refused
// as before where it does not.
TEST(GltfPose, QuantizedAttributesWithTheExtension) {
  const auto dir = testsupport::temp_dir("gltf_pose_quantized");
  GltfFixture f;
  // Three VEC3 of SHORT, each padded to 8 bytes (glTF aligns vertex attributes to 4 bytes).
  const std::vector<int16_t> pos = {0, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0};
  const int acc = f.accessor(pos.data(), pos.size() * 2, 5122, 3, "VEC3");
  f.doc["accessors"][acc]["normalized"] = true;
  f.doc["bufferViews"][f.doc["accessors"][acc]["bufferView"].get<int>()]["byteStride"] = 8;
  f.node({{"mesh", f.mesh(acc)}});
  const auto plain = f.write_gltf(dir, "plain");
  EXPECT_NE(error_of(plain).find("POSITION (accessors[0]): expected FLOAT components"), std::string::npos)
      << error_of(plain);
  f.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  f.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "quantized"));
  ASSERT_EQ(s.meshes.size(), 1u);
  expect_near(s.meshes[0].positions[1], {1, 0, 0}, "normalized SHORT 32767");
  expect_near(s.meshes[0].positions[2], {0, 1, 0}, "normalized SHORT 32767");

  // Normals: normalized BYTE is read; UNSIGNED_BYTE (which cannot point backwards) is refused by key.
  const std::vector<int8_t> up = {0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0};
  const int normals = f.accessor(up.data(), up.size(), 5120, 3, "VEC3");
  f.doc["accessors"][normals]["normalized"] = true;
  f.doc["bufferViews"][f.doc["accessors"][normals]["bufferView"].get<int>()]["byteStride"] = 4;
  f.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = normals;
  const scenes::Scene n = scenes::import_gltf(f.write_gltf(dir, "normals"));
  expect_near(n.meshes[0].normals[0], {0, 0, 1}, "normalized BYTE 127");
  f.doc["accessors"][normals]["componentType"] = 5121;
  const auto unsigned_normals = f.write_gltf(dir, "unsigned");
  EXPECT_EQ(error_of(unsigned_normals),
            unsigned_normals.string() + ": meshes[0].primitives[0].attributes.NORMAL (accessors[1]): expected FLOAT or "
                                        "normalized BYTE or SHORT components (KHR_mesh_quantization)");
}

}  // namespace
