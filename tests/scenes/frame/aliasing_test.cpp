// The aliasing measure (scenes/frame/aliasing.h) against closed-form answers: a ground plane seen straight
// down through an orthographic camera, lit straight down through the tutorial's fixed 20 m box, so one map
// texel is 20 / map_size metres and one pixel 20 / width metres, and every pixel's ratio is their quotient;
// then a slanted light, which stretches texels on the ground by 1 / cos(angle) along one axis. Plus the
// summary statistics and the measure of the view-following techniques on `duel` (cascades beat one map).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"

namespace {

scenes::Scene ground_scene(glm::vec3 light_direction) {
  scenes::Scene s;
  scenes::Mesh m;
  m.name = "ground";
  m.positions = {{-30, 0, -30}, {30, 0, -30}, {30, 0, 30}, {-30, 0, 30}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
  s.meshes.push_back(m);
  s.materials.push_back(scenes::Material{});
  scenes::Instance inst;
  inst.casts_shadows = false;
  s.instances.push_back(inst);
  s.objects.push_back("ground");
  scenes::Camera cam;
  cam.position = {0, 5, 0};
  cam.target = {0, 0, 0};
  cam.up = {0, 0, -1};
  cam.projection = scenes::Orthographic{-10, 10, -10, 10, 0.1f, 20};
  s.cameras.push_back(cam);
  scenes::Light l;
  l.name = "sun";
  l.direction = glm::normalize(light_direction);
  s.lights.push_back(l);
  return s;
}

frame::AliasingImage measure(const scenes::Scene& s, int size, int map_size, int threads = 2) {
  frame::FrameConfig o;
  o.width = o.height = size;
  o.map_size = map_size;
  o.params["fit"] = std::string("fixed");
  o.aliasing = true;
  raster::Renderer r(threads);
  const frame::Frame f = frame::render_frame(s, o, r);
  EXPECT_EQ(f.aliasing.size(), 1u);
  return f.aliasing.at(0);
}

TEST(Aliasing, StraightDownIsTheQuotientOfTexelAndPixelSizes) {
  const scenes::Scene s = ground_scene({0, -1, 0});
  for (const auto& [size, map, expected] : {std::tuple{256, 1024, 0.25f}, {256, 128, 2.0f}, {128, 128, 1.0f}}) {
    const frame::AliasingImage a = measure(s, size, map);
    EXPECT_EQ(a.measured, size_t(size) * size_t(size));
    EXPECT_NEAR(a.max, expected, 1e-3f * expected);
    EXPECT_NEAR(a.p95, expected, 1e-3f * expected);
    EXPECT_NEAR(a.mean, expected, 1e-3f * expected);
    EXPECT_NEAR(a.storage_factor(), expected * expected, 3e-3f * expected * expected);
  }
}

TEST(Aliasing, ASlantedLightStretchesTexelsAlongOneAxis) {
  // Light 60° from the vertical, in the x-y plane: a texel's footprint on the ground is 1 / cos 60° = 2 times
  // longer along x; the worse axis is x.
  const float a = glm::radians(60.0f);
  const scenes::Scene s = ground_scene({std::sin(a), -std::cos(a), 0});
  const frame::AliasingImage m = measure(s, 128, 128);
  EXPECT_NEAR(m.p95, 2.0f, 2e-3f);
  EXPECT_NEAR(m.mean, 2.0f, 2e-3f);
}

TEST(Aliasing, BackFacingAndEmptyPixelsAreNotMeasured) {
  // Lit from below: the ground faces away from the light everywhere.
  const frame::AliasingImage m = measure(ground_scene({0, 1, 0}), 64, 128);
  EXPECT_EQ(m.measured, 0u);
  for (float r : m.ratio) EXPECT_EQ(r, frame::kUnmeasured);
  // A camera looking past the ground sees nothing.
  scenes::Scene s = ground_scene({0, -1, 0});
  s.cameras[0].position = {0, 5, 0};
  s.cameras[0].target = {0, 10, 0};
  s.cameras[0].up = {0, 0, -1};
  const frame::AliasingImage e = measure(s, 32, 128);
  for (float r : e.ratio) EXPECT_EQ(r, frame::kEmpty);
}

TEST(Aliasing, SameAtEveryThreadCount) {
  const scenes::Scene s = scenes::builtin_scene("duel");
  frame::FrameConfig o;
  o.width = 240;
  o.height = 135;
  o.technique = shading::tech::Technique::cascades;
  o.aliasing = true;
  std::vector<float> first;
  for (int threads : {0, 1, 2}) {
    raster::Renderer r(threads);
    const frame::Frame f = frame::render_frame(s, o, r);
    if (first.empty()) first = f.aliasing.at(0).ratio;
    else EXPECT_EQ(f.aliasing.at(0).ratio, first) << threads << " threads";
  }
}

TEST(Aliasing, CascadesResolveDuelBetterThanOneMapOfTheSameMemory) {
  const scenes::Scene s = scenes::builtin_scene("duel");
  auto p95 = [&](shading::tech::Technique t, int map_size) {
    frame::FrameConfig o;
    o.width = 480;
    o.height = 270;
    o.technique = t;
    o.map_size = map_size;
    o.aliasing = true;
    raster::Renderer r(2);
    return frame::render_frame(s, o, r).aliasing.at(0).p95;
  };
  const float uniform = p95(shading::tech::Technique::shadowmap, 2048);
  const float cascades = p95(shading::tech::Technique::cascades, 1024);  // 4 × 1024²: the same texel count
  EXPECT_LT(cascades * 4.0f, uniform) << "uniform " << uniform << ", cascades " << cascades;
}

}  // namespace
