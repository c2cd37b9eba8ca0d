// PCSS on a point light's cube map (the cube's `soft_shadows = pcss`) on constructed scenes: under a straight
// occluder edge the penumbra on the floor follows similar triangles for a spherical light of radius R, R (d_r −
// d_b) / d_b metres each side, within 15 % of the ideal 16-tap profile, so it grows linearly with R and with
// (d_r − d_b) / d_b; a point with no blocker in its search region is lit exactly (the early exit); nothing is
// lit behind a hemispherical light; the answer is the same at any thread count; and settings that cannot work
// together are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "shading/techniques/cube_pcss.h"
#include "shading/techniques/omni_read.h"
#include "tests/shading/techniques/pcss_test_util.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

constexpr float kRange = 20.0f;
constexpr float kFloor = -8.0f;  // the receiver, 8 m below the light

ShadowConfig config(double radius) {
  ShadowConfig c;
  c.technique = Technique::cube;
  c.map_size = 512;
  c.depth_format = DepthFormat::d32f;
  c.bias.mode = BiasMode::constant;
  c.bias.constant = 0.0002f;
  c.params = {{"soft_shadows", std::string("pcss")}, {"light_radius", radius}};
  return c;
}

LightDesc point_light(LightType type = LightType::point) {
  return LightDesc{type, {0.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, kRange};
}

// An occluder covering x < 0 at height y (its edge along z at x = 0), over the floor.
techtest::Soup edge_scene(float occluder_y) {
  techtest::Soup s;
  s.horizontal(-30, 0, -30, 30, occluder_y);
  s.horizontal(-30, 30, -30, 30, kFloor);
  return s;
}

std::unique_ptr<LightShadow> build(raster::Renderer& r, const techtest::Soup& s, const ShadowConfig& c,
                                   const LightDesc& light = point_light()) {
  auto shadow = plan_cube(light, c, PlanInputs{});
  shadow->build(r, CasterGeometry{s.positions, s.indices});
  return shadow;
}

float visibility_at(const LightShadow& s, glm::vec3 p, glm::vec2 frag = {0.0f, 0.0f}) {
  const ShadowQuery q{p, {0.0f, 1.0f, 0.0f}, frag};
  float v = -1.0f;
  s.visibility(std::span(&q, 1), std::span(&v, 1));
  return v;
}

// The mean visibility across the edge's shadow on the floor (x = 0 there: the edge is straight below the
// light), averaged over many pixels along z, each its own turn of the disc; the distance between its 10 % and
// 90 % crossings.
float penumbra_width(const LightShadow& s, float step) {
  const int rows = 192;
  return techtest::measured_width(1.5f, step, rows, [&](float x, int j, glm::vec2 frag) {
    return visibility_at(s, {x, kFloor, -0.5f + float(j) / rows}, frag);
  });
}

TEST(CubePcss, PenumbraFollowsSimilarTriangles) {
  raster::Renderer r(testsupport::test_threads());
  struct Case {
    float occluder_y, radius;
  };
  // (d_r − d_b) / d_b: 3 (occluder 2 m below the light) and 1 (4 m below); R 0.05 m and 0.1 m.
  std::vector<float> ratios;
  for (const Case& k : {Case{-2.0f, 0.05f}, Case{-2.0f, 0.1f}, Case{-4.0f, 0.1f}, Case{-4.0f, 0.2f}}) {
    const auto shadow = build(r, edge_scene(k.occluder_y), config(k.radius));
    const float d_b = -k.occluder_y, d_r = -kFloor;
    const float kernel = k.radius * (d_r - d_b) / d_b;  // metres on the floor
    const float ideal = techtest::ideal_pcss_width(kernel);
    const float measured = penumbra_width(*shadow, kernel / 40.0f);
    std::printf("occluder %.0f m below, R %.2f m: penumbra (10-90 %%) %.4f m, ideal %.4f m\n", d_b, k.radius,
                measured, ideal);
    EXPECT_NEAR(measured, ideal, 0.15f * ideal) << "occluder " << d_b << " m, R " << k.radius;
    ratios.push_back(measured / kernel);
  }
  // Linear in R and in (d_r − d_b) / d_b: the width per metre of kernel is the same in every case, within 10 %.
  for (float q : ratios) EXPECT_NEAR(q, ratios[0], 0.1f * ratios[0]);
}

TEST(CubePcss, NoBlockerInTheSearchRegionIsLitAtOnce) {
  raster::Renderer r(testsupport::test_threads());
  const auto shadow = build(r, edge_scene(-2.0f), config(0.1));
  // Far on the lit side, and straight up (nothing drawn there).
  EXPECT_EQ(visibility_at(*shadow, {3.0f, kFloor, 0.2f}, {5, 9}), 1.0f);
  EXPECT_EQ(visibility_at(*shadow, {0.3f, 4.0f, -0.2f}, {1, 2}), 1.0f);
  // Deep in the umbra: dark.
  EXPECT_EQ(visibility_at(*shadow, {-3.0f, kFloor, 0.2f}, {5, 9}), 0.0f);
  // Across the −Y face's edge with +X (45° from straight down), on the lit side, well away from the shadow.
  EXPECT_EQ(visibility_at(*shadow, {8.5f, kFloor, 0.3f}, {2, 7}), 1.0f);
}

TEST(CubePcss, NothingIsLitBehindAHemisphericalLight) {
  raster::Renderer r(testsupport::test_threads());
  const auto shadow = build(r, edge_scene(-2.0f), config(0.1), point_light(LightType::hemispherical));
  EXPECT_EQ(visibility_at(*shadow, {0.3f, 4.0f, -0.2f}), 0.0f);
  EXPECT_EQ(visibility_at(*shadow, {3.0f, kFloor, 0.2f}), 1.0f);
}

TEST(CubePcss, SameAnswerAtAnyThreadCount) {
  std::vector<float> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    const auto shadow = build(r, edge_scene(-2.0f), config(0.1));
    std::vector<float> v;
    for (float x = -1.0f; x <= 1.0f; x += 0.013f) v.push_back(visibility_at(*shadow, {x, kFloor, 0.1f}, {x * 100, 3}));
    if (first.empty()) first = v;
    else EXPECT_EQ(v, first) << threads << " threads";
  }
}

TEST(CubePcss, RefusesSettingsThatCannotWorkTogether) {
  auto refused = [](ShadowConfig c, const std::string& what) {
    try {
      plan_cube(point_light(), c, PlanInputs{});
      ADD_FAILURE() << "expected a refusal containing: " << what;
    } catch (const TechniqueError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  ShadowConfig c = config(0.1);
  c.params["moments"] = std::string("vsm");
  refused(c, "pcss and moments = vsm both replace the filter");
  c = config(0.1);
  c.filter = FilterKind::poisson;
  refused(c, "filter: poisson is not used with soft_shadows = pcss");
  c = config(0.1);
  c.params.erase("soft_shadows");
  refused(c, "light_radius: the light's size is read by soft_shadows = pcss only");
  // The cube lists both settings; the paraboloid lists neither.
  EXPECT_FALSE(param_problem(Technique::cube, "soft_shadows", ParamValue(std::string("pcss"))).has_value());
  EXPECT_TRUE(param_problem(Technique::paraboloid, "soft_shadows", ParamValue(std::string("pcss"))).has_value());
}

}  // namespace
