// Cascades whose slices store filterable moments (the `moments` parameter): each slice's map, encoded and blurred
// on its own, against the closed form. Under an occluder plane ESM gives exp(c (z_occ − z_r)) with z the slice's
// linear depth, so in slice k the exponent is c Δy / depth_extent_k (the plane has no variance, the blur leaves it
// unchanged); under a square occluder the slices of an atlas must not bleed into each other, every slice
// reading its own region. Settings that cannot work together are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shading/techniques/cascades.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// The camera over the floor (technique_test_util.h).
CameraView camera() { return techtest::floor_camera(); }


PlanInputs inputs(const techtest::Soup& casters) {
  PlanInputs in;
  Box b{glm::vec3(1e30f), glm::vec3(-1e30f)};
  for (const glm::vec3& p : casters.positions) b.min = glm::min(b.min, p), b.max = glm::max(b.max, p);
  in.casters = b;
  in.scene_receivers = Box{{-20.0f, 0.0f, -48.0f}, {20.0f, 0.0f, 12.0f}};
  in.receivers = in.scene_receivers;
  in.camera = camera();
  in.eye = in.camera.eye;
  in.camera_view_proj = in.camera.proj * in.camera.view;
  return in;
}

ShadowConfig config(const std::string& moments, const std::string& layout) {
  ShadowConfig c;
  c.technique = Technique::cascades;
  c.map_size = 512;
  c.depth_format = DepthFormat::d32f;
  c.bias.mode = BiasMode::none;
  c.params = {{"moments", moments}, {"cascades", 3.0}, {"map_layout", layout}, {"esm_c", 40.0}};
  return c;
}

const LightDesc kSun{LightType::directional, {}, {0.0f, -1.0f, 0.0f}};

float visibility_at(const LightShadow& s, glm::vec3 p) {
  const ShadowQuery q{p, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f}};
  float v = -1.0f;
  s.visibility(std::span(&q, 1), std::span(&v, 1));
  return v;
}

// Points on the floor along the view, one per slice at least (the floor enters the view 4.1 m ahead).
constexpr float kDistances[] = {5.0f, 7.0f, 10.0f, 14.0f, 20.0f, 35.0f, 50.0f};

TEST(CascadeMoments, EsmUnderAnOccluderPlaneIsExponentialInEachSlice) {
  raster::Renderer r(testsupport::test_threads());
  techtest::Soup occluder;
  occluder.horizontal(-30, 30, -60, 20, 2.0f);  // covers every slice's map
  for (const char* layout : {"atlas", "separate"}) {
    ShadowConfig c = config("esm", layout);
    c.params["esm_c"] = 2.0;  // a visibility well inside (0, 1): exp(−4 / extent)
    const PlanInputs in = inputs(occluder);
    auto shadow = plan_cascades(kSun, c, in);
    shadow->build(r, CasterGeometry{occluder.positions, occluder.indices});
    // The same plan, for the slices' split distances and depth extents.
    CascadeSettings s;
    s.count = 3;
    const CascadePlan plan = plan_cascade_fits(kSun, s, c.map_size, in);
    std::set<size_t> slices;
    for (float d : kDistances) {
      const glm::vec3 p = camera().eye + glm::vec3(0.0f, 0.0f, -d);
      const glm::vec3 floor(p.x, 0.0f, p.z);
      const SliceChoice k = choose_slice(plan.splits, 0.0f, view_distance(camera(), floor));
      const float expected = std::exp(2.0f * (0.0f - 2.0f) / plan.fits[k.slice].depth_extent);
      const float got = visibility_at(*shadow, floor);
      slices.insert(k.slice);
      EXPECT_NEAR(got, expected, 2e-3f * expected + 1e-6f) << layout << ", slice " << k.slice << " at " << d << " m";
    }
    EXPECT_EQ(slices.size(), 3u) << "the points must fall in every slice";
  }
}

TEST(CascadeMoments, EachSliceOfAnAtlasReadsItsOwnRegion) {
  raster::Renderer r(testsupport::test_threads());
  // A 4 × 4 m square 1 m above the floor, 20 m in front of the camera: its shadow is in a far slice only.
  techtest::Soup occluder;
  occluder.horizontal(-2, 2, -10, -6, 1.0f);
  for (const char* kind : {"esm", "vsm", "evsm2", "evsm4"}) {
    for (const char* layout : {"atlas", "separate"}) {
      auto shadow = plan_cascades(kSun, config(kind, layout), inputs(occluder));
      shadow->build(r, CasterGeometry{occluder.positions, occluder.indices});
      // Under the square's middle: dark. Everywhere else on the floor (every slice, both sides): lit.
      EXPECT_LT(visibility_at(*shadow, {0.0f, 0.0f, -8.0f}), 0.05f) << kind << " " << layout;
      EXPECT_LT(visibility_at(*shadow, {1.2f, 0.0f, -6.8f}), 0.05f) << kind << " " << layout;
      for (glm::vec3 p : {glm::vec3(0, 0, 10), glm::vec3(3, 0, 6), glm::vec3(-1, 0, 0), glm::vec3(3.5f, 0, -8),
                          glm::vec3(0, 0, -12), glm::vec3(0, 0, -25), glm::vec3(-6, 0, -40)})
        EXPECT_GT(visibility_at(*shadow, p), 0.95f) << kind << " " << layout << " at " << p.x << ", " << p.z;
    }
  }
}

TEST(CascadeMoments, SameAnswerAtAnyThreadCount) {
  techtest::Soup occluder;
  occluder.horizontal(-2, 2, -10, -6, 1.0f);
  std::vector<float> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    auto shadow = plan_cascades(kSun, config("vsm", "atlas"), inputs(occluder));
    shadow->build(r, CasterGeometry{occluder.positions, occluder.indices});
    std::vector<float> got;
    for (float x = -3.0f; x <= 3.0f; x += 0.37f)
      for (float z = -12.0f; z <= -4.0f; z += 0.29f) got.push_back(visibility_at(*shadow, {x, 0.0f, z}));
    if (first.empty()) first = got;
    else EXPECT_EQ(got, first) << threads << " threads";
  }
}

TEST(CascadeMoments, RefusesAWarpAndAFilterItWouldIgnore) {
  techtest::Soup occluder;
  occluder.horizontal(-2, 2, -10, -6, 1.0f);
  ShadowConfig c = config("vsm", "atlas");
  c.params["cascade_warp"] = std::string("lispsm");
  EXPECT_THROW(plan_cascades(kSun, c, inputs(occluder)), TechniqueError);
  c = config("vsm", "atlas");
  c.filter = FilterKind::poisson;
  try {
    plan_cascades(kSun, c, inputs(occluder));
    FAIL() << "a Poisson filter with moments was accepted";
  } catch (const TechniqueError& e) {
    EXPECT_NE(std::string(e.what()).find("filter: poisson is not used with moments = vsm"), std::string::npos)
        << e.what();
  }
  // Without moments, the same filter is taken.
  c.params["moments"] = std::string("none");
  EXPECT_NO_THROW(plan_cascades(kSun, c, inputs(occluder)));
}

}  // namespace
