// The ray-cast reference against shadows known in closed form: a square over a floor under the sun, a sphere
// under a point light, a spot's cone on an empty floor; pixel for pixel away from the edges (a margin stated per
// test). And the same bits at any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "scenes/frame/frame.h"
#include "scenes/reference/exact_visibility.h"
#include "scenes/reference/frame_reference.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/reference/analytic_scenes.h"
#include "tests/support.h"

namespace {

frame::FrameConfig view(int w = 320, int h = 240) {
  frame::FrameConfig c;
  c.width = w, c.height = h;
  return c;
}

struct Agreement {
  size_t compared = 0, lit = 0, shadowed = 0, wrong = 0;
};

// Floor pixels (y near 0) compared with `exact_lit(p)`, which returns 1 lit, 0 shadowed, -1 too near an edge.
template <class Exact>
Agreement compare_floor(const reference::FrameReference& ref, Exact exact_lit) {
  const frame::SurfaceRecord& r = *ref.shadows_off.surface;
  Agreement a;
  for (size_t p = 0; p < r.pixels(); ++p) {
    if (!r.covered[p] || std::fabs(r.position[p].y) > 1e-3f) continue;
    const int want = exact_lit(r.position[p]);
    if (want < 0) continue;
    ++a.compared;
    (want ? a.lit : a.shadowed)++;
    const bool got = ref.exact.reached[p] && ref.exact.visible[p];
    a.wrong += got != bool(want);
  }
  return a;
}

TEST(ExactVisibility, SquareOverFloorUnderTheSun) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSquareOverFloor);
  raster::Renderer renderer(testsupport::test_threads());
  const reference::FrameReference ref = reference::reference_for(scene, view(), renderer);
  const glm::vec3 to_light = -glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  // The floor point p is shadowed when p + t · to_light meets y = 1 inside |x|, |z| < 0.5. Margin: 2 cm from the
  // square's edge (a pixel here is about 2.3 cm).
  const Agreement a = compare_floor(ref, [&](glm::vec3 p) {
    const glm::vec3 q = p + (1.0f / to_light.y) * to_light;
    const float inside = 0.5f - std::max(std::fabs(q.x), std::fabs(q.z));
    return std::fabs(inside) < 0.02f ? -1 : inside > 0.0f ? 0 : 1;
  });
  EXPECT_GT(a.shadowed, 300u);  // the part of the shadow the square itself does not hide
  EXPECT_GT(a.lit, 10000u);
  EXPECT_EQ(a.wrong, 0u);
  // The square's own top sees the sun.
  const frame::SurfaceRecord& r = *ref.shadows_off.surface;
  size_t top = 0, top_lit = 0;
  for (size_t p = 0; p < r.pixels(); ++p)
    if (r.covered[p] && std::fabs(r.position[p].y - 1.0f) < 1e-3f) ++top, top_lit += ref.exact.visible[p];
  EXPECT_GT(top, 1000u);
  EXPECT_EQ(top_lit, top);
  EXPECT_EQ(ref.exact.rays, size_t(std::count(r.covered.begin(), r.covered.end(), 1)));
}

TEST(ExactVisibility, SphereUnderPointLight) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSphereUnderPointLight);
  raster::Renderer renderer(testsupport::test_threads());
  const reference::FrameReference ref = reference::reference_for(scene, view(), renderer);
  const glm::vec3 light(0.4f, 3.0f, 0.2f), centre(0.0f, 1.0f, 0.0f);
  // Shadowed when the segment to the light passes within 0.5 of the centre. Margin: 1.5 cm around that distance
  // (the 64 x 32 sphere's facets lie within 2 mm of the sphere; a pixel is about 2 cm at the shadow).
  const Agreement a = compare_floor(ref, [&](glm::vec3 p) {
    const glm::vec3 d = light - p;
    const float t = std::clamp(glm::dot(centre - p, d) / glm::dot(d, d), 0.0f, 1.0f);
    const float dist = glm::length(p + t * d - centre);
    return std::fabs(dist - 0.5f) < 0.015f ? -1 : dist < 0.5f ? 0 : 1;
  });
  EXPECT_GT(a.shadowed, 1000u);
  EXPECT_GT(a.lit, 10000u);
  EXPECT_EQ(a.wrong, 0u);
}

TEST(ExactVisibility, SpotConeOnAnEmptyFloor) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSpotOverFloor);
  raster::Renderer renderer(testsupport::test_threads());
  const reference::FrameReference ref = reference::reference_for(scene, view(), renderer);
  const float radius = 3.0f * std::tan(25.0f * 3.14159265f / 180.0f);
  const Agreement a = compare_floor(ref, [&](glm::vec3 p) {
    const float r = std::hypot(p.x, p.z);
    return std::fabs(r - radius) < 0.02f ? -1 : r < radius ? 1 : 0;
  });
  EXPECT_GT(a.shadowed, 1000u);  // outside the cone: the light does not reach
  EXPECT_GT(a.lit, 1000u);
  EXPECT_EQ(a.wrong, 0u);
}

TEST(ExactVisibility, SameBitsAtAnyThreadCount) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSphereUnderPointLight);
  std::vector<uint8_t> first;
  for (int threads : {0, 1, 2, 5}) {
    raster::Renderer renderer(threads);
    const reference::FrameReference ref = reference::reference_for(scene, view(200, 150), renderer);
    std::vector<uint8_t> bits = ref.exact.visible;
    bits.insert(bits.end(), ref.exact.reached.begin(), ref.exact.reached.end());
    if (first.empty()) first = bits;
    else EXPECT_EQ(bits, first) << threads << " threads";
  }
}

TEST(ExactVisibility, RecordAndLightsMustAgree) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSquareOverFloor);
  const reference::OcclusionScene occ(scenes::flatten(scene, scenes::InstanceFilter::casters));
  EXPECT_EQ(occ.triangles(), scenes::triangle_count(scene, scenes::InstanceFilter::casters));
  const frame::SurfaceRecord record(4, 4, 2);  // two light channels, one light
  raster::ThreadPool pool(0);
  EXPECT_THROW(reference::cast_shadow_rays(occ, record, scene.lights, 1e-3f, pool), reference::ReferenceError);
}

}  // namespace
