// Every model in ../shared/assets loads, with the triangle counts (per file and per scene, instancing included)
// and world-space bounding boxes its README gives; load times are recorded. Skips when the assets are absent.
#include <chrono>

#include <gtest/gtest.h>

#include "scenes/gltf_import.h"
#include "scenes/scene_build.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/scene_checks.h"
#include "tests/support.h"

namespace {

struct Asset {
  const char* file;
  size_t triangles;        // sum over the file's primitives
  size_t scene_triangles;  // every node instance drawn
  glm::vec3 min, max;      // README bounding box (4 significant digits)
};

// From ../shared/assets/README.md.
const Asset kAssets[] = {
    {"stanford_dragon/dragon_vrip.glb", 871414, 871414, {-0.1083f, 0.05273f, -0.05041f}, {0.09657f, 0.1972f, 0.04121f}},
    {"stanford_dragon/dragon_vrip_res2.glb", 202520, 202520, {-0.1082f, 0.05274f, -0.05035f},
     {0.09641f, 0.1971f, 0.04114f}},
    {"toy_car/ToyCar.gltf", 108936, 108936, {-0.03499f, -0.01621f, -0.03698f}, {0.03845f, 0.01262f, 0.03698f}},
    {"flight_helmet/FlightHelmet.gltf", 94722, 94722, {-0.2036f, -2.142e-05f, -0.1716f}, {0.1629f, 0.716f, 0.2f}},
    {"sheen_chair/SheenChair.gltf", 39936, 39936, {-0.414f, -6.978e-05f, -0.2767f}, {0.4125f, 0.6862f, 0.2935f}},
    {"antique_camera/AntiqueCamera.gltf", 20066, 20066, {-1.626f, -0.0008065f, -1.895f}, {0.9715f, 7.208f, 1.5f}},
    {"damaged_helmet/DamagedHelmet.gltf", 15452, 15452, {-0.9475f, -0.901f, -1.187f}, {0.9425f, 0.901f, 0.8128f}},
    {"vulkan_subpass_scene/subpass_scene_opaque.gltf", 11132, 23388, {-11, -9.714f, -11}, {11, 0.4864f, 11}},
    {"glass_vase_flowers/GlassVaseFlowers.gltf", 10218, 14036, {-0.05352f, 0, -0.06829f}, {0.1638f, 0.2032f, 0.0742f}},
    {"vulkan_teapot/teapot.gltf", 9128, 9128, {-30.4f, -17.22f, -20}, {33.94f, 14.28f, 20}},
    {"lantern/Lantern.gltf", 5394, 5394, {-3.922f, 0.1839f, -2.316f}, {11.57f, 25.85f, 2.316f}},
    {"vulkan_terrain/terrain.gltf", 5202, 5202, {-1, 0.0002443f, -1}, {1, 0.2888f, 1}},
    {"cesium_man/CesiumMan.gltf", 4672, 4672, {-0.5691f, -3.678e-17f, -0.131f}, {0.5691f, 1.506f, 0.1809f}},
    {"duck/Duck.gltf", 4212, 4212, {-0.693f, 0.09929f, -0.6133f}, {0.9618f, 1.64f, 0.5393f}},
    {"suzanne/Suzanne.gltf", 3936, 3936, {-1.337f, -0.9746f, -0.8008f}, {1.337f, 0.9502f, 0.8257f}},
    {"cesium_milk_truck/CesiumMilkTruck.gltf", 2856, 3624, {-1.396f, 0.001452f, -2.431f}, {1.396f, 2.584f, 2.438f}},
    {"avocado/Avocado.gltf", 682, 682, {-0.02128f, -4.774e-05f, -0.01381f}, {0.02128f, 0.06285f, 0.01381f}},
    {"fox/Fox.gltf", 576, 576, {-12.59f, -0.1217f, -88.09f}, {12.59f, 78.91f, 66.62f}},
    {"kenney_tree/tree.glb", 280, 280, {-0.06651f, 0, -1.067f}, {1.067f, 1.941f, 0.06651f}},
    {"box/Box.gltf", 12, 12, {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}},
    {"box_textured/BoxTextured.gltf", 12, 12, {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}},
};

// Test names and ctest entries show the file, not the struct's bytes.
void PrintTo(const Asset& a, std::ostream* os) { *os << a.file; }

class AssetTest : public testing::TestWithParam<Asset> {};

TEST_P(AssetTest, LoadsWithReadmeCountsAndBounds) {
  SHADOWLAB_REQUIRE_ASSETS();
  const Asset& a = GetParam();
  const auto path = testsupport::assets_dir() / a.file;

  const auto start = std::chrono::steady_clock::now();
  const scenes::Scene scene = scenes::load_scene(path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("load_ms", std::to_string(int(seconds * 1000.0)));
  if (a.triangles > 100000) std::printf("  %s: %zu triangles loaded in %.0f ms\n", a.file, a.triangles, seconds * 1e3);

  EXPECT_EQ(scenes::triangle_count(scene), a.scene_triangles);
  // Per file: every mesh once, leaving out the flipped copies made for mirrored instances.
  size_t per_file = 0;
  for (const auto& m : scene.meshes)
    if (!m.name.ends_with(" (mirrored)")) per_file += m.triangle_count();
  EXPECT_EQ(per_file, a.triangles);

  const scenes::Aabb box = scenes::scene_bounds(scene);
  const float tolerance = 1e-3f * glm::length(a.max - a.min);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], a.min[k], tolerance) << "axis " << k;
    EXPECT_NEAR(box.max[k], a.max[k], tolerance) << "axis " << k;
  }
  for (const auto& m : scene.meshes) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  }
  EXPECT_FALSE(scene.cameras.empty());
  EXPECT_FALSE(scene.lights.empty());
}

std::string asset_name(const testing::TestParamInfo<Asset>& info) {
  std::string name = info.param.file;
  name = name.substr(name.find('/') + 1);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(SharedAssets, AssetTest, testing::ValuesIn(kAssets), asset_name);

TEST(SharedAssets, SubpassSceneNanNormalsAreReplaced) {
  SHADOWLAB_REQUIRE_ASSETS();
  const auto path = testsupport::assets_dir() / "vulkan_subpass_scene/subpass_scene_opaque.gltf";
  const scenes::Scene s = scenes::import_gltf(path);
  size_t replaced = 0;
  for (const std::string& w : s.warnings)
    if (const size_t at = w.find("NORMAL: "); at != std::string::npos) replaced += std::stoul(w.substr(at + 8));
  EXPECT_EQ(replaced, 112u);
}

TEST(SharedAssets, TinyAssetsHaveConsistentWinding) {
  SHADOWLAB_REQUIRE_ASSETS();
  for (const char* file : {"box/Box.gltf", "duck/Duck.gltf", "suzanne/Suzanne.gltf"}) {
    const scenes::Scene s = scenes::load_scene(testsupport::assets_dir() / file);
    EXPECT_GT(testsupport::winding_agreement(s), 0.99) << file;
  }
}

}  // namespace
