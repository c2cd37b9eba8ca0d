// PCSS on cascades (`soft_shadows = pcss`): each slice's blocker search and penumbra estimate work in that
// slice's own texels, with the light's angular diameter converted by the slice's projection, so the penumbra in
// metres of a straight occluder edge is the same whichever slice covers it (slices whose texels differ in size
// by several times) and grows linearly with the receiver–blocker distance, against the ideal width of the
// similar-triangles kernel. Identical at any thread count; settings that cannot work together are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shading/techniques/cascades.h"
#include "tests/shading/techniques/pcss_test_util.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// The camera over the floor (technique_test_util.h).
CameraView camera() { return techtest::floor_camera(); }

constexpr float kAngle = 8.0f;  // degrees
constexpr int kMap = 1024;


const LightDesc kSun{LightType::directional, {}, {0.0f, -1.0f, 0.0f}};

// The floor, and an occluder over x < 0 at height h along the whole view; 120 m wide, so that the far slices'
// crops, as wide as the frustum there, are not cut to the floor's width.
techtest::Soup edge_scene(float h) {
  techtest::Soup s;
  s.horizontal(-60, 0, -50, 12, h);
  s.horizontal(-60, 60, -50, 12, 0.0f);
  return s;
}

PlanInputs inputs(float h) {
  PlanInputs in;
  in.casters = Box{{-60.0f, 0.0f, -50.0f}, {60.0f, h, 12.0f}};
  in.scene_receivers = Box{{-60.0f, 0.0f, -50.0f}, {60.0f, 0.0f, 12.0f}};
  in.receivers = in.scene_receivers;
  in.camera = camera();
  in.eye = in.camera.eye;
  in.camera_view_proj = in.camera.proj * in.camera.view;
  return in;
}

ShadowConfig config() {
  ShadowConfig c;
  c.technique = Technique::cascades;
  c.map_size = kMap;
  c.depth_format = DepthFormat::d32f;
  c.bias.mode = BiasMode::constant;
  c.bias.constant = 0.0005f;
  c.params = {{"cascades", 3.0}, {"soft_shadows", std::string("pcss")}, {"light_angle", double(kAngle)}};
  return c;
}

float visibility_at(const LightShadow& s, glm::vec3 p, glm::vec2 frag) {
  const ShadowQuery q{p, {0.0f, 1.0f, 0.0f}, frag};
  float v = -1.0f;
  s.visibility(std::span(&q, 1), std::span(&v, 1));
  return v;
}

// The floor's z whose view distance is `d` (view distance is linear in z on the floor, x does not change it).
float floor_z_at(float d) {
  const float d0 = view_distance(camera(), {0, 0, 0}), d1 = view_distance(camera(), {0, 0, -1});
  return (d - d0) / (d1 - d0) * -1.0f;
}

// The 10-90 % penumbra width across the edge at x = 0 on the floor around z, the visibility at each x averaged
// over 128 pixels (each its own turn of the disc) spread over ±0.25 m of z.
float penumbra_width(const LightShadow& s, float z, float step, float reach) {
  const int rows = 128;
  return techtest::measured_width(reach, step, rows, [&](float x, int j, glm::vec2 frag) {
    return visibility_at(s, {x, 0.0f, z - 0.25f + 0.5f * float(j) / rows}, frag);
  });
}

TEST(CascadePcss, PenumbraInMetresIsTheSameInEverySliceAndLinearInDistance) {
  raster::Renderer r(testsupport::test_threads());
  const float tan_half = std::tan(0.5f * kAngle * 3.14159265f / 180.0f);
  CascadeSettings cs;
  cs.count = 3;
  std::vector<std::vector<float>> ratio(3);  // per slice: width / h
  for (float h : {1.5f, 3.0f, 4.5f}) {
    const PlanInputs in = inputs(h);
    const CascadePlan plan = plan_cascade_fits(kSun, cs, kMap, in);
    auto shadow = plan_cascades(kSun, config(), in);
    const techtest::Soup scene = edge_scene(h);
    shadow->build(r, CasterGeometry{scene.positions, scene.indices, {}});
    const float ideal = techtest::ideal_pcss_width(h * tan_half);
    float texel_lo = 1e30f, texel_hi = 0.0f;
    for (size_t k = 0; k < 3; ++k) {
      // Three quarters into slice k (the nearest slice's first metres lie at the bottom edge of the view, where
      // its map ends), clear of its ends by more than the rows' spread.
      const float mid = plan.splits[k] + 0.75f * (plan.splits[k + 1] - plan.splits[k]);
      const float z = floor_z_at(mid);
      ASSERT_EQ(choose_slice(plan.splits, 0.0f, view_distance(camera(), {0, 0, z - 0.3f})).slice, k);
      ASSERT_EQ(choose_slice(plan.splits, 0.0f, view_distance(camera(), {0, 0, z + 0.3f})).slice, k);
      const float texel = 2.0f / plan.fits[k].proj[0][0] / float(kMap);  // metres per texel along x
      texel_lo = std::min(texel_lo, texel), texel_hi = std::max(texel_hi, texel);
      ASSERT_LT(visibility_at(*shadow, {-1.5f * ideal, 0.0f, z}, {1, 2}), 0.01f) << "under the occluder, slice " << k;
      const float measured = penumbra_width(*shadow, z, 0.004f, 1.2f * ideal);
      std::printf("[ cascade pcss ] h = %.1f m, slice %zu (%.1f m away, texel %.4f m): penumbra %.4f m = %.1f texels, "
                  "ideal %.4f m\n",
                  h, k, mid, texel, measured, measured / texel, ideal);
      EXPECT_NEAR(measured, ideal, 0.1f * ideal) << "h = " << h << ", slice " << k;
      ratio[k].push_back(measured / h);
    }
    EXPECT_GT(texel_hi / texel_lo, 2.0f) << "the slices' texels must differ in size";
  }
  for (size_t k = 0; k < 3; ++k) {
    const auto [lo, hi] = std::minmax_element(ratio[k].begin(), ratio[k].end());
    EXPECT_LT(*hi / *lo, 1.1f) << "slice " << k << ": width / distance must not depend on the distance";
  }
}

TEST(CascadePcss, SameAnswerAtAnyThreadCount) {
  const PlanInputs in = inputs(2.0f);
  const techtest::Soup scene = edge_scene(2.0f);
  std::vector<float> first;
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    auto shadow = plan_cascades(kSun, config(), in);
    shadow->build(r, CasterGeometry{scene.positions, scene.indices, {}});
    std::vector<float> got;
    for (int k = 0; k < 200; ++k)
      got.push_back(visibility_at(*shadow, {-0.3f + 0.003f * float(k), 0.0f, 8.0f - 0.2f * float(k)},
                                  {float(k), float(3 * k)}));
    if (first.empty()) first = got;
    else EXPECT_EQ(got, first) << threads << " threads";
  }
}

void expect_refused(ShadowConfig c, const std::string& what) {
  try {
    plan_cascades(kSun, c, inputs(2.0f));
    ADD_FAILURE() << "not refused: " << what;
  } catch (const TechniqueError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(CascadePcss, RefusesWhatCannotWorkTogether) {
  ShadowConfig c = config();
  c.params["moments"] = std::string("vsm");
  expect_refused(c, "shadow.params.soft_shadows: pcss and moments = vsm both replace the filter");
  c = config();
  c.params["cascade_warp"] = std::string("lispsm");
  expect_refused(c, "shadow.params.soft_shadows: pcss needs orthographic slices");
  c = config();
  c.filter = FilterKind::poisson;
  expect_refused(c, "shadow.filter: poisson is not used with soft_shadows = pcss");
  // light_angle belongs to pcss and cascades; soft_shadows to cascades alone.
  EXPECT_FALSE(param_problem(Technique::cascades, "light_angle", ParamValue(4.0)).has_value());
  EXPECT_TRUE(param_problem(Technique::shadowmap, "soft_shadows", ParamValue(std::string("pcss"))).has_value());
}

}  // namespace
