// Built-in scenes: each builds, is non-empty with finite bounds, its camera sees every object, its lights are
// valid; and each shows what it was made for (tutorial light direction, pyramid light under the ceiling facing
// down, objects all around the paraboloid light, projective casters that move with time, the duel's long shadow).
#include <cmath>

#include <gtest/gtest.h>

#include "scenes/builtin_scenes.h"
#include "scenes/camera_math.h"
#include "scenes/primitives.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/scene_checks.h"

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(BuiltinScenes, ListHasTheIssueScenes) {
  std::vector<std::string> names;
  for (const auto& b : scenes::list_builtin_scenes()) {
    names.emplace_back(b.name);
    EXPECT_FALSE(b.description.empty());
    EXPECT_EQ(b.description.find('\n'), std::string_view::npos);
    EXPECT_TRUE(scenes::is_builtin_scene(b.name));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"tutorial", "tutorial-spot", "pyramid", "paraboloid", "projective",
                                              "duel"}));
  EXPECT_FALSE(scenes::is_builtin_scene("nope"));
}

class BuiltinTest : public testing::TestWithParam<std::string> {};

TEST_P(BuiltinTest, BuildsAndIsFramed) {
  const scenes::Scene s = scenes::builtin_scene(GetParam());
  EXPECT_EQ(s.name, GetParam());
  EXPECT_FALSE(s.description.empty());
  ASSERT_FALSE(s.instances.empty());
  EXPECT_GT(scenes::triangle_count(s), 100u);
  EXPECT_GT(scenes::triangle_count(s, scenes::InstanceFilter::casters), 0u);
  const scenes::Aabb box = scenes::scene_bounds(s);
  ASSERT_FALSE(box.empty());
  EXPECT_TRUE(finite(box.min) && finite(box.max));
  EXPECT_EQ(testsupport::winding_agreement(s), 1.0);
  EXPECT_TRUE(s.warnings.empty());

  ASSERT_FALSE(s.cameras.empty());
  const scenes::Camera& cam = s.cameras[0];
  const glm::mat4 vp = scenes::projection_matrix(cam, 1.0f) * scenes::view_matrix(cam);
  for (uint32_t o = 0; o < s.objects.size(); ++o) {
    const glm::vec3 c = scenes::object_bounds(s, o).center();
    const glm::vec4 clip = vp * glm::vec4(c, 1.0f);
    ASSERT_GT(clip.w, 0.0f) << s.objects[o];
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(clip[k] / clip.w), 1.0f) << s.objects[o] << " axis " << k;
  }
  ASSERT_FALSE(s.lights.empty());
  for (const scenes::Light& l : s.lights) {
    EXPECT_EQ(scenes::light_problem(l), std::nullopt) << l.name;
    EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-6f);
    if (l.type != scenes::LightType::directional) {
      EXPECT_GT(l.range, 0.0f);
    }
    EXPECT_NE(l.shadow.technique, scenes::ShadowTechnique::none);
  }
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinTest,
                         testing::Values("tutorial", "tutorial-spot", "pyramid", "paraboloid", "projective", "duel"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n) c = c == '-' ? '_' : c;
                           return n;
                         });

TEST(BuiltinScenes, TutorialMatchesTheTutorial) {
  const scenes::Scene s = scenes::builtin_scene("tutorial");
  EXPECT_EQ(s.objects, (std::vector<std::string>{"room", "cylinder", "sphere"}));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, scenes::LightType::directional);
  EXPECT_NEAR(glm::distance(scenes::to_light(s.lights[0]), glm::normalize(glm::vec3(0.5f, 2, 2))), 0.0f, 1e-6f);
  // Issue 16: front faces and a 2048² map, measured against the ray-cast reference (builtin_tutorial.cpp).
  EXPECT_FALSE(s.lights[0].shadow.cull_front);
  EXPECT_EQ(s.lights[0].shadow.map_size, 2048u);
  const scenes::Scene spot = scenes::builtin_scene("tutorial-spot");
  EXPECT_EQ(spot.lights[0].type, scenes::LightType::spot);
  EXPECT_EQ(spot.lights[0].position, glm::vec3(5, 20, 20));
  EXPECT_TRUE(spot.lights[0].shadow.cull_front) << "thick walls, back faces into the map";
  EXPECT_EQ(spot.meshes, s.meshes) << "the same room";
}

TEST(BuiltinScenes, PyramidLightHangsUnderTheCeilingFacingDown) {
  const scenes::Scene s = scenes::builtin_scene("pyramid");
  const scenes::Light& l = s.lights[0];
  EXPECT_EQ(l.type, scenes::LightType::hemispherical);
  EXPECT_EQ(l.shadow.technique, scenes::ShadowTechnique::pyramid);
  EXPECT_EQ(l.direction, glm::vec3(0, -1, 0));
  const scenes::Aabb room = scenes::object_bounds(s, 0);
  EXPECT_GT(l.position.y, room.max.y - 1.0f);
  EXPECT_LT(l.position.y, room.max.y);
}

TEST(BuiltinScenes, ParaboloidLightHasObjectsAllAround) {
  const scenes::Scene s = scenes::builtin_scene("paraboloid");
  const scenes::Light& l = s.lights[0];
  EXPECT_EQ(l.shadow.technique, scenes::ShadowTechnique::paraboloid);
  int sides[6] = {};
  for (uint32_t o = 1; o < s.objects.size(); ++o) {  // object 0 is the ground
    const glm::vec3 d = scenes::object_bounds(s, o).center() - l.position;
    sides[d.x > 0 ? 0 : 1]++;
    sides[d.z > 0 ? 2 : 3]++;
    const scenes::Aabb b = scenes::object_bounds(s, o);
    if (b.max.y > l.position.y) sides[4]++;
    if (b.min.y < l.position.y) sides[5]++;
  }
  for (int k = 0; k < 6; ++k) EXPECT_GE(sides[k], 3) << "side " << k;
}

TEST(BuiltinScenes, ProjectiveFiguresAreCastersThatMoveOnTheTerrain) {
  const scenes::Scene a = scenes::builtin_scene("projective", {0.0});
  const scenes::Scene b = scenes::builtin_scene("projective", {3.0});
  EXPECT_EQ(a.lights[0].shadow.technique, scenes::ShadowTechnique::projective);
  const scenes::TerrainShape ground{{40.0f, 40.0f}, 96, 0.8f, 14.0f, 7};
  ASSERT_EQ(a.objects.size(), 6u);
  for (const scenes::Instance& i : a.instances) EXPECT_EQ(i.casts_shadows, i.object != 0) << i.name;
  EXPECT_EQ(scenes::object_bounds(a, 0), scenes::object_bounds(b, 0)) << "the terrain stays";
  for (uint32_t o = 1; o < a.objects.size(); ++o) {
    const scenes::Aabb fa = scenes::object_bounds(a, o), fb = scenes::object_bounds(b, o);
    EXPECT_GT(glm::distance(fa.center(), fb.center()), 0.3f) << a.objects[o];
    const glm::vec3 feet = scenes::instance_bounds(a, scenes::object_instances(a, o)[0]).center();
    EXPECT_NEAR(fa.min.y, scenes::terrain_height(ground, feet.x, feet.z), 1e-3f) << "stands on the ground";
  }
}

TEST(BuiltinScenes, ProjectiveFiguresStayInViewWhileTheyWalk) {
  for (double t = 0.0; t < 60.0; t += 0.75) {
    const scenes::Scene s = scenes::builtin_scene("projective", {t});
    const glm::mat4 vp = scenes::projection_matrix(s.cameras[0], 1.0f) * scenes::view_matrix(s.cameras[0]);
    for (uint32_t o = 1; o < s.objects.size(); ++o) {
      const scenes::Aabb b = scenes::object_bounds(s, o);
      for (const glm::vec3& p : {b.min, b.max}) {
        const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
        EXPECT_LT(std::max(std::abs(clip.x), std::abs(clip.y)), clip.w) << s.objects[o] << " at t = " << t;
      }
    }
  }
}

TEST(BuiltinScenes, DuelShadowRunsTowardsTheViewer) {
  const scenes::Scene s = scenes::builtin_scene("duel");
  const scenes::Light& sun = s.lights[0];
  const scenes::Camera& cam = s.cameras[0];
  const scenes::Aabb tree = scenes::object_bounds(s, 1);
  EXPECT_EQ(s.objects[1], "tree");
  // The light travels from behind the tree towards the camera, and the camera looks at the light.
  const glm::vec3 to_camera = cam.position - tree.center();
  EXPECT_GT(glm::dot(glm::normalize(glm::vec2(sun.direction.x, sun.direction.z)),
                     glm::normalize(glm::vec2(to_camera.x, to_camera.z))), 0.99f);
  // Shadow length of the tree top on flat ground: height / tan(elevation).
  const float elevation = std::asin(-sun.direction.y);
  EXPECT_GT(tree.max.y / std::tan(elevation), 40.0f);
  EXPECT_GT(glm::length(to_camera), 50.0f) << "distant";
}

}  // namespace
