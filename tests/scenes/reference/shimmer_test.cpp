// Shimmer: the motions are the size asked (a sub-pixel camera slide measured in pixels at the target, a light
// turned by the angle asked), no motion gives no flip at all, and a coarse map shimmers more than a fine one.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "scenes/camera_math.h"
#include "scenes/reference/shimmer.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/reference/analytic_scenes.h"
#include "tests/support.h"

namespace {

const char* kBoxOnFloor = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [6, 6]}},
    {"name": "box", "primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}
  ],
  "cameras": [{"position": [3, 5, 6], "target": [0, 0, 0]}],
  "lights": [{"type": "directional", "direction": [-0.5, -1, -0.3],
              "shadow": {"technique": "shadowmap", "filter": "hard", "bias": "slope"}}]
})";

TEST(Shimmer, MotionsAreTheSizeAsked) {
  const scenes::Scene scene = testsupport::scene_from_json(kBoxOnFloor);
  const scenes::Scene slid = reference::moved(scene, 0, 240, {0.25f, 0.0f});
  // The old target seen by the slid camera: a quarter pixel to the left of the centre of a 320 x 240 frame.
  const glm::mat4 vp = scenes::projection_matrix(slid.cameras[0], 320.0f / 240.0f) * scenes::view_matrix(slid.cameras[0]);
  const glm::vec4 clip = vp * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const float x_pixels = (clip.x / clip.w + 1.0f) * 0.5f * 320.0f;
  EXPECT_NEAR(x_pixels, 160.0f - 0.25f, 1e-3f);
  EXPECT_EQ(slid.lights[0].direction, scene.lights[0].direction);
  const scenes::Scene turned = reference::moved(scene, 0, 240, {0.0f, 0.5f});
  const float angle = glm::degrees(std::acos(glm::dot(turned.lights[0].direction, scene.lights[0].direction)));
  EXPECT_NEAR(angle, 0.5f, 0.01f);
  EXPECT_EQ(turned.cameras[0], scene.cameras[0]);
  // A point light straight above the scene's centre moves by the angle about it.
  scenes::Scene lamp = testsupport::scene_from_json(testsupport::kSphereUnderPointLight);
  lamp.lights[0].position = scenes::scene_bounds(lamp).center() + glm::vec3(0.0f, 2.0f, 0.0f);
  const scenes::Scene lamp_turned = reference::moved(lamp, 0, 240, {0.0f, 3.0f});
  const glm::vec3 c = scenes::scene_bounds(lamp).center();
  const float lamp_angle = glm::degrees(std::acos(glm::dot(glm::normalize(lamp.lights[0].position - c),
                                                           glm::normalize(lamp_turned.lights[0].position - c))));
  EXPECT_NEAR(lamp_angle, 3.0f, 0.01f);
}

TEST(Shimmer, NoMotionNoFlipsAndCoarseMapsShimmerMore) {
  const scenes::Scene scene = testsupport::scene_from_json(kBoxOnFloor);
  raster::Renderer r(testsupport::test_threads());
  frame::FrameConfig c;
  c.width = 320, c.height = 240;
  c.map_size = 256;
  const reference::LightShimmer still = reference::shimmer(scene, c, r, {0.0f, 0.0f}).at(0);
  EXPECT_GT(still.compared, 20000u);
  EXPECT_EQ(still.flips, 0u);
  const reference::LightShimmer coarse = reference::shimmer(scene, c, r, {0.0f, 1.0f}).at(0);
  c.map_size = 4096;
  const reference::LightShimmer fine = reference::shimmer(scene, c, r, {0.0f, 1.0f}).at(0);
  EXPECT_GT(coarse.exact_flips, 0u);  // the shadow really moves
  EXPECT_GT(coarse.shimmering, 2 * fine.shimmering + 10);
  std::printf("light turned 1 degree: shimmer 256: %.3f %%, 4096: %.3f %% (exact flips %zu)\n", coarse.percent(),
              fine.percent(), coarse.exact_flips);
}

}  // namespace
