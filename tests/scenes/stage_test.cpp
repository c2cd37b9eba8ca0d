// Staging a bare glTF model (scenes/stage.h): a model without lights gets a sun where asked and a ground under
// its bounds, a Z-up model is turned upright, and a file's own light keeps it from being staged; built from
// tiny glTF files written by the test (a box 1 × 2 × 4 m, its long side along +Z).
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scenes/camera_math.h"
#include "scenes/scene_error.h"
#include "scenes/scene_queries.h"
#include "scenes/stage.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

// A closed box from (0, 0, 0) to (1, 2, 4), twelve triangles; with a point light when `light`.
std::filesystem::path write_box(const std::filesystem::path& dir, const std::string& name, bool light,
                                float scale = 1.0f) {
  testsupport::GltfFixture f;
  std::vector<glm::vec3> p;
  for (int i = 0; i < 8; ++i)
    p.push_back(scale * glm::vec3(float(i & 1), 2.0f * float((i >> 1) & 1), 4.0f * float(i >> 2)));
  const std::vector<uint32_t> idx = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                     2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  f.node({{"mesh", f.mesh(f.positions(p), f.indices(idx))}});
  if (light) {
    f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"name", "bulb"}, {"type", "point"}, {"intensity", 50}}};
    f.node({{"translation", {0.5, 5, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  }
  return f.write_gltf(dir, name);
}

const scenes::Light* find_light(const scenes::Scene& s, const std::string& name) {
  for (const scenes::Light& l : s.lights)
    if (l.name == name) return &l;
  return nullptr;
}

}  // namespace

TEST(Stage, BareModelGetsASunAGroundAndACamera) {
  const auto dir = testsupport::temp_dir("stage_bare");
  scenes::StageOptions o;
  o.sun = glm::vec2(90.0f, 30.0f);
  const scenes::StagedScene s = scenes::load_model_staged(write_box(dir, "box", false), o);
  ASSERT_EQ(s.scene.lights.size(), 1u);
  const scenes::Light* sun = find_light(s.scene, "sun");
  ASSERT_NE(sun, nullptr);
  EXPECT_EQ(sun->type, scenes::LightType::directional);
  // Azimuth 90 (from +Z towards +X), elevation 30: it shines towards −X and down.
  EXPECT_NEAR(sun->direction.x, -std::cos(glm::radians(30.0f)), 1e-5f);
  EXPECT_NEAR(sun->direction.y, -0.5f, 1e-5f);
  EXPECT_NEAR(sun->direction.z, 0.0f, 1e-5f);
  // The ground: 3 × the larger horizontal side (4 m along z), its top at the model's base, centred under it.
  const scenes::Aabb all = scenes::scene_bounds(s.scene), casters = scenes::scene_bounds(s.scene, scenes::InstanceFilter::casters);
  EXPECT_NEAR(all.max.x - all.min.x, 12.0f, 1e-4f);
  EXPECT_NEAR(all.max.z - all.min.z, 12.0f, 1e-4f);
  EXPECT_NEAR(all.min.y, 0.0f, 1e-5f);
  EXPECT_NEAR(0.5f * (all.min.x + all.max.x), 0.5f, 1e-4f);
  // The ground is drawn into the maps, as a floor is (filtered maps need their receivers in the map), unless
  // asked otherwise (projective shadows, whose receivers cast nothing).
  EXPECT_NEAR(casters.max.z - casters.min.z, 12.0f, 1e-4f);
  ASSERT_EQ(s.scene.cameras.size(), 1u);
  EXPECT_GE(s.notes.size(), 3u);  // sun, ground, camera
  scenes::Scene receivers = scenes::load_model_staged(write_box(dir, "box3", false), o).scene;
  scenes::ground_receives_only(receivers);
  const scenes::Aabb model = scenes::scene_bounds(receivers, scenes::InstanceFilter::casters);
  EXPECT_NEAR(model.max.z - model.min.z, 4.0f, 1e-5f);  // the model alone

  o.ground = false;
  const scenes::StagedScene bare = scenes::load_model_staged(write_box(dir, "box2", false), o);
  EXPECT_FALSE(bare.scene.staged_ground.has_value());
  EXPECT_NEAR(scenes::scene_bounds(bare.scene).max.x - scenes::scene_bounds(bare.scene).min.x, 1.0f, 1e-5f);
}

// A model of any size a float holds is staged alike, its ground and camera scaled with it: a 1 mm floor on the
// ground and the camera's radius made a 1e-6 m model a speck, and at 1e20 m the camera's radius, view vector and
// near · far overflowed (an error about a camera the file does not have, or an empty frame).
TEST(Stage, ModelsOfAnySizeAreFramedAlike) {
  const auto dir = testsupport::temp_dir("stage_scales");
  scenes::StageOptions o;
  o.sun = glm::vec2(90.0f, 30.0f);
  const glm::vec3 centre_unit(0.5f, 1.0f, 2.0f);
  for (const float scale : {1e-10f, 1e-6f, 1.0f, 1e20f, 1e35f}) {
    const scenes::StagedScene s = scenes::load_model_staged(write_box(dir, "box", false, scale), o);
    const scenes::Aabb all = scenes::scene_bounds(s.scene);
    EXPECT_NEAR((all.max.x - all.min.x) / scale, 12.0f, 1e-3f) << scale;  // the ground: 3 × 4 m, scaled
    ASSERT_EQ(s.scene.cameras.size(), 1u);
    const glm::mat4 vp = scenes::projection_matrix(s.scene.cameras[0], 16.0f / 9.0f) * scenes::view_matrix(s.scene.cameras[0]);
    const glm::vec4 clip = vp * glm::vec4(scale * centre_unit, 1.0f);
    ASSERT_TRUE(std::isfinite(clip.x) && std::isfinite(clip.y) && std::isfinite(clip.w) && clip.w > 0.0f) << scale;
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-3f) << scale;  // the model's centre at the frame's centre
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-3f) << scale;
    EXPECT_GT(clip.z / clip.w, -1.0f);
    EXPECT_LT(clip.z / clip.w, 1.0f);
  }
}

// --up z: the model's +Z becomes +Y (its 4 m side stands up) and the ground goes under the turned model.
TEST(Stage, ZUpModelIsTurnedUpright) {
  const auto dir = testsupport::temp_dir("stage_zup");
  scenes::StageOptions o;
  o.up = scenes::StageOptions::Up::z;
  const scenes::StagedScene s = scenes::load_model_staged(write_box(dir, "box", false), o);
  ASSERT_EQ(s.scene.staged_ground, std::optional<uint32_t>(1));
  const scenes::Aabb m = scenes::object_bounds(s.scene, 0);  // the model
  EXPECT_NEAR(m.max.y - m.min.y, 4.0f, 1e-5f);
  EXPECT_NEAR(m.max.z - m.min.z, 2.0f, 1e-5f);
  EXPECT_NEAR(m.max.x - m.min.x, 1.0f, 1e-5f);
  EXPECT_NEAR(scenes::scene_bounds(s.scene).min.y, m.min.y, 1e-5f);  // the ground's top at the model's base
}

// The ground catches the sun's whole shadow of the model: the box stood up (4 m tall on a 1 × 2 m footprint)
// under a sun 30° up casts its top 6.9 m away, beyond three times its footprint (a 6 m ground, as the antique
// camera on its tripod had its head's shadow cut at the ground's corner); every corner of the model's box,
// carried along the sun's direction down to the ground, lands on it, for suns all around.
TEST(Stage, TheGroundHoldsTheModelsShadow) {
  const auto dir = testsupport::temp_dir("stage_shadow");
  const auto file = write_box(dir, "box", false);
  for (const float az : {0.0f, 45.0f, 90.0f, 200.0f, 315.0f}) {
    scenes::StageOptions o;
    o.up = scenes::StageOptions::Up::z;
    o.sun = glm::vec2(az, 30.0f);
    const scenes::StagedScene s = scenes::load_model_staged(file, o);
    ASSERT_EQ(s.scene.staged_ground, std::optional<uint32_t>(1));
    const scenes::Aabb m = scenes::object_bounds(s.scene, 0), ground = scenes::object_bounds(s.scene, 1);
    const glm::vec3 d = s.scene.lights.at(0).direction;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 p((i & 1) ? m.max.x : m.min.x, (i & 2) ? m.max.y : m.min.y, (i & 4) ? m.max.z : m.min.z);
      const glm::vec3 q = p + d * ((p.y - m.min.y) / -d.y);
      EXPECT_GE(q.x, ground.min.x) << az;
      EXPECT_LE(q.x, ground.max.x) << az;
      EXPECT_GE(q.z, ground.min.z) << az;
      EXPECT_LE(q.z, ground.max.z) << az;
    }
    // No wider than it needs: a tenth to spare around the farthest point of the shadow.
    EXPECT_LT(ground.max.x - ground.min.x, 2.2f * (4.0f / std::tan(glm::radians(30.0f)) + 1.2f)) << az;
  }
}

// Every --up axis: the model's own up direction becomes +Y by a rotation (no mirror), the ground under it.
TEST(Stage, EachUpAxisTurnsTheModelUpright) {
  const auto dir = testsupport::temp_dir("stage_up");
  const auto file = write_box(dir, "box", false);
  using Up = scenes::StageOptions::Up;
  for (const auto& [up, axis] : {std::pair{Up::y, glm::vec3(0, 1, 0)}, std::pair{Up::z, glm::vec3(0, 0, 1)},
                                 std::pair{Up::minus_y, glm::vec3(0, -1, 0)}, std::pair{Up::minus_z, glm::vec3(0, 0, -1)}}) {
    scenes::StageOptions o;
    o.up = up;
    const scenes::StagedScene s = scenes::load_model_staged(file, o);
    const glm::mat3 turn(s.scene.instances.at(0).transform);
    const glm::vec3 v = turn * axis;
    EXPECT_NEAR(v.x, 0.0f, 1e-5f) << int(up);
    EXPECT_NEAR(v.y, 1.0f, 1e-5f) << int(up);
    EXPECT_NEAR(v.z, 0.0f, 1e-5f) << int(up);
    EXPECT_NEAR(glm::determinant(turn), 1.0f, 1e-5f) << int(up);
    const scenes::Aabb m = scenes::object_bounds(s.scene, 0);
    EXPECT_NEAR(scenes::scene_bounds(s.scene).min.y, m.min.y, 1e-5f) << int(up);  // the ground under it
  }
}

// A file with its own light is shown as it is: no sun and no ground; a sun below the horizon is refused.
TEST(Stage, FileLightsAreKeptAndBadSunsRefused) {
  const auto dir = testsupport::temp_dir("stage_lit");
  const scenes::StagedScene s = scenes::load_model_staged(write_box(dir, "lit", true), {});
  ASSERT_EQ(s.scene.lights.size(), 1u);
  EXPECT_EQ(s.scene.lights[0].name, "bulb");
  EXPECT_NEAR(scenes::scene_bounds(s.scene).max.x - scenes::scene_bounds(s.scene).min.x, 1.0f, 1e-5f);
  scenes::StageOptions o;
  o.sun = glm::vec2(0.0f, -10.0f);
  EXPECT_THROW(scenes::load_model_staged(write_box(dir, "box", false), o), scenes::SceneError);
}
