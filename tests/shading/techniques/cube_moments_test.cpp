// A point light's cube map whose faces store filterable moments (the cube's `moments` parameter): each face's
// radial distance, encoded and blurred on its own, against the closed form. Under an occluder plane 1 m below
// the light, a receiver 3 m below it in direction θ from straight down has the occluder at 1/cos θ and itself at
// 3/cos θ along the ray, so ESM's visibility is exp(c (1 − 3) / (range · cos θ)); the points span the −Y face
// and the four side faces, across their edges. The answer is the same at any thread count; settings that cannot
// work together are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "shading/cube_face.h"
#include "shading/techniques/omni_read.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

constexpr float kRange = 10.0f;
const LightDesc kPoint{LightType::point, {0.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, kRange};

ShadowConfig config(const std::string& moments) {
  ShadowConfig c;
  c.technique = Technique::cube;
  c.map_size = 256;
  c.depth_format = DepthFormat::d32f;
  c.bias.mode = BiasMode::none;
  c.params = {{"moments", moments}, {"esm_c", 5.0}};
  return c;
}

// The occluder: a 60 × 60 m plane 1 m below the light, facing it.
techtest::Soup plane() {
  techtest::Soup s;
  s.horizontal(-30, 30, -30, 30, -1.0f);
  return s;
}

float visibility_at(const LightShadow& s, glm::vec3 p) {
  const ShadowQuery q{p, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f}};
  float v = -1.0f;
  s.visibility(std::span(&q, 1), std::span(&v, 1));
  return v;
}

// A receiver 3 m below the light, θ from straight down, at azimuth φ.
glm::vec3 receiver(float theta_deg, float phi_deg) {
  const float r = 3.0f * std::tan(glm::radians(theta_deg)), phi = glm::radians(phi_deg);
  return {r * std::cos(phi), -3.0f, r * std::sin(phi)};
}

TEST(CubeMoments, EsmUnderAnOccluderPlaneIsExponentialOnEveryFace) {
  raster::Renderer r(testsupport::test_threads());
  const techtest::Soup occluder = plane();
  for (bool seamless : {true, false}) {
    ShadowConfig c = config("esm");
    c.params["seamless"] = seamless;
    auto shadow = plan_cube(kPoint, c, PlanInputs{});
    shadow->build(r, CasterGeometry{occluder.positions, occluder.indices});
    std::set<int> faces;
    for (float theta : {0.0f, 20.0f, 40.0f, 44.0f, 46.0f, 55.0f, 65.0f}) {
      for (float phi : {0.0f, 30.0f, 45.0f, 100.0f, 200.0f, 280.0f}) {
        const glm::vec3 p = receiver(theta, phi);
        const float expected = std::exp(5.0f * (1.0f - 3.0f) / (kRange * std::cos(glm::radians(theta))));
        faces.insert(shading::cube_coord(p).face);
        EXPECT_NEAR(visibility_at(*shadow, p), expected, 0.01f * expected)
            << "seamless " << seamless << ", theta " << theta << ", phi " << phi;
      }
    }
    EXPECT_EQ(faces.size(), 5u) << "the points must fall on the -Y face and the four side faces";
    // Above the light nothing is in the map (cleared to the far distance): lit.
    EXPECT_FLOAT_EQ(visibility_at(*shadow, {0.5f, 2.0f, 0.3f}), 1.0f);
  }
}

TEST(CubeMoments, EveryKindIsDarkBelowThePlaneAndLitAboveIt) {
  raster::Renderer r(testsupport::test_threads());
  // A 2 × 2 m square 1 m below the light: under it dark, beside it (outside its shadow) lit, on every face.
  techtest::Soup square;
  square.horizontal(-1, 1, -1, 1, -1.0f);
  for (const char* kind : {"esm", "vsm", "evsm2", "evsm4"}) {
    ShadowConfig c = config(kind);
    c.params["esm_c"] = 80.0;
    auto shadow = plan_cube(kPoint, c, PlanInputs{});
    shadow->build(r, CasterGeometry{square.positions, square.indices});
    EXPECT_LT(visibility_at(*shadow, receiver(0.0f, 0.0f)), 0.05f) << kind;
    EXPECT_LT(visibility_at(*shadow, receiver(30.0f, 45.0f)), 0.05f) << kind;  // under a corner's diagonal
    for (glm::vec3 p : {receiver(60.0f, 0.0f), receiver(60.0f, 90.0f), glm::vec3(5, 0, 0), glm::vec3(0, 4, 0),
                        glm::vec3(-3, 1, -3)})
      EXPECT_GT(visibility_at(*shadow, p), 0.95f) << kind << " at " << p.x << ", " << p.y << ", " << p.z;
  }
}

TEST(CubeMoments, SameAnswerAtAnyThreadCount) {
  const techtest::Soup occluder = plane();
  std::vector<float> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    auto shadow = plan_cube(kPoint, config("evsm4"), PlanInputs{});
    shadow->build(r, CasterGeometry{occluder.positions, occluder.indices});
    std::vector<float> v;
    for (float theta = 0.0f; theta < 80.0f; theta += 3.7f)
      for (float phi = 0.0f; phi < 360.0f; phi += 23.0f) v.push_back(visibility_at(*shadow, receiver(theta, phi)));
    if (first.empty()) first = v;
    else EXPECT_EQ(v, first) << threads << " threads";
  }
}

TEST(CubeMoments, RefusesAFilterThatWouldDoNothing) {
  ShadowConfig c = config("vsm");
  c.filter = FilterKind::poisson;
  try {
    plan_cube(kPoint, c, PlanInputs{});
    FAIL() << "a Poisson filter with moments must be refused";
  } catch (const TechniqueError& e) {
    EXPECT_NE(std::string(e.what()).find("filter: poisson is not used with moments = vsm"), std::string::npos)
        << e.what();
  }
  c.filter = FilterKind::pcf;
  c.filter_params.pcf_taps = true;
  EXPECT_THROW(plan_cube(kPoint, c, PlanInputs{}), TechniqueError);
  // moments belongs to the cube (and cascades): the paraboloid does not list it.
  EXPECT_TRUE(param_problem(Technique::paraboloid, "moments", ParamValue(std::string("vsm"))).has_value());
  EXPECT_FALSE(param_problem(Technique::cube, "moments", ParamValue(std::string("vsm"))).has_value());
}

}  // namespace
