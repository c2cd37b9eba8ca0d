// The geometry of the view-following techniques, checked by brute force on random views, lights and scenes:
// the practical split scheme, the slice clipped to the receivers, cascade crops that hold their slice's
// receivers and every caster that can shadow them, LiSPSM's degenerate case and its body in the unit cube, and
// the seed-003 face maps tiling the frustum without gaps (boundaries only shared).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "shading/techniques/cascades.h"
#include "shading/techniques/frustum_faces.h"
#include "shading/techniques/view_fit.h"
#include "shading/techniques/view_frustum.h"

namespace {

using namespace shading::tech;

struct Rng {
  std::mt19937 g;
  explicit Rng(uint32_t seed) : g(seed) {}
  float uniform(float a, float b) { return std::uniform_real_distribution<float>(a, b)(g); }
  glm::vec3 unit() {
    for (;;) {
      const glm::vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const float l = glm::length(v);
      if (l > 0.1f && l <= 1.0f) return v / l;
    }
  }
};

CameraView make_camera(glm::vec3 eye, glm::vec3 forward, float fovy_deg, float aspect, float n, float f) {
  CameraView c;
  c.eye = eye;
  c.forward = glm::normalize(forward);
  const glm::vec3 up = std::abs(c.forward.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  c.view = glm::lookAt(eye, eye + c.forward, up);
  c.proj = glm::perspective(glm::radians(fovy_deg), aspect, n, f);
  c.near = n, c.far = f;
  return c;
}

CameraView random_camera(Rng& r) {
  return make_camera({r.uniform(-5, 5), r.uniform(0.5f, 4), r.uniform(-5, 5)}, r.unit(), r.uniform(30, 80),
                     r.uniform(0.8f, 2.0f), r.uniform(0.05f, 0.5f), r.uniform(20, 80));
}

// A random point of the frustum slice [a, b] (trilinear in its corners: the slice is a hexahedron whose
// cross-sections at fixed view distance are rectangles, so this covers it).
glm::vec3 point_in_slice(const std::array<glm::vec3, 8>& c, Rng& r) {
  const float u = r.uniform(0, 1), v = r.uniform(0, 1), w = r.uniform(0, 1);
  auto quad = [&](size_t o) {
    const glm::vec3 lo = glm::mix(c[o + 0], c[o + 1], u), hi = glm::mix(c[o + 3], c[o + 2], u);
    return glm::mix(lo, hi, v);
  };
  return glm::mix(quad(0), quad(4), w);
}

bool in_box(glm::vec3 p, const Box& b) {
  return p.x >= b.min.x && p.y >= b.min.y && p.z >= b.min.z && p.x <= b.max.x && p.y <= b.max.y && p.z <= b.max.z;
}

glm::vec4 clip_of(const FittedMap& m, glm::vec3 p) { return m.proj * m.view * glm::vec4(p, 1.0f); }

TEST(PracticalSplits, UniformLogarithmicAndBetween) {
  const auto u = practical_splits(1.0f, 101.0f, 4, 0.0f);
  const auto g = practical_splits(1.0f, 81.0f, 4, 1.0f);
  const auto h = practical_splits(1.0f, 81.0f, 4, 0.5f);
  for (int i = 0; i <= 4; ++i) {
    EXPECT_NEAR(u[size_t(i)], 1.0f + 25.0f * float(i), 1e-4f);
    EXPECT_NEAR(g[size_t(i)], std::pow(3.0f, float(i)), 1e-3f);  // 81^(i/4)
    EXPECT_NEAR(h[size_t(i)], 0.5f * std::pow(3.0f, float(i)) + 0.5f * (1.0f + 20.0f * float(i)), 1e-3f);
  }
  EXPECT_EQ(g.front(), 1.0f);
  EXPECT_EQ(g.back(), 81.0f);
}

TEST(ChooseSlice, BySplitDistanceWithABlendBand) {
  const float s[] = {1.0f, 2.0f, 4.0f, 8.0f};
  EXPECT_EQ(choose_slice(s, 0.0f, 0.5f).slice, 0u);
  EXPECT_EQ(choose_slice(s, 0.0f, 1.99f).slice, 0u);
  EXPECT_EQ(choose_slice(s, 0.0f, 2.0f).slice, 1u);
  EXPECT_EQ(choose_slice(s, 0.0f, 100.0f).slice, 2u);
  EXPECT_EQ(choose_slice(s, 0.0f, 3.9f).next_weight, 0.0f);
  // Band of a quarter of slice 1 (2 .. 4): from 3.5 to 4 the weight of slice 2 rises from 0 to 1.
  EXPECT_EQ(choose_slice(s, 0.25f, 3.4f).next_weight, 0.0f);
  EXPECT_NEAR(choose_slice(s, 0.25f, 3.75f).next_weight, 0.5f, 1e-6f);
  EXPECT_EQ(choose_slice(s, 0.25f, 7.9f).next_weight, 0.0f);  // the last slice blends into nothing
}

// The receivers' range is that of the frustum's part inside their box, not of the box's corners: a box beside
// the camera (x from 5 to 6, 60° square frustum, half-width 0.577 d at distance d) meets the view from
// d = 5 / tan 30° = 8.66 on, though its near corners lie at distance 0, before the camera's near plane. The
// corners' range put a perspective warp's near plane at 0.1 and left the toy car's face maps almost no texels.
TEST(ReceiverViewRange, IsTheFrustumsPartInsideTheBox) {
  const CameraView cam = make_camera({0, 0, 0}, {0, 0, -1}, 60, 1.0f, 0.1f, 100);
  const ViewRange beside = receiver_view_range(cam, Box{{5, -0.5f, -20}, {6, 0.5f, 0}});
  const float enter = 5.0f / std::tan(glm::radians(30.0f));
  EXPECT_NEAR(beside.near, enter, 0.02f * (20.0f - enter));  // within its 0.1 % pad and rounding
  EXPECT_LE(beside.near, enter);
  EXPECT_NEAR(beside.far, 20.0f, 0.02f);
  EXPECT_GE(beside.far, 20.0f);
  // A box around the camera starts at the near plane; one beyond the far plane ends there.
  const ViewRange around = receiver_view_range(cam, Box{{-1, -1, -200}, {1, 1, 1}});
  EXPECT_FLOAT_EQ(around.near, 0.1f);
  EXPECT_FLOAT_EQ(around.far, 100.0f);
  // A box outside the view keeps its corners' range (clamped to the camera's).
  const ViewRange behind = receiver_view_range(cam, Box{{-1, -1, 5}, {1, 1, 9}});
  EXPECT_FLOAT_EQ(behind.near, 0.1f);
  EXPECT_GT(behind.far, behind.near);
}

TEST(ClipSliceToBox, BoundsHoldEveryPointOfTheIntersection) {
  Rng r(7);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const CameraView cam = random_camera(r);
    const float a = r.uniform(cam.near, 5.0f), b = a + r.uniform(1.0f, 15.0f);
    const auto corners = slice_corners(cam, a, b);
    const glm::vec3 c(r.uniform(-6, 6), r.uniform(-1, 3), r.uniform(-6, 6));
    const glm::vec3 h(r.uniform(1, 8), r.uniform(0.2f, 3), r.uniform(1, 8));
    const Box box{c - h, c + h};
    const std::vector<glm::vec3> pts = clip_slice_to_box(corners, box);
    Box bounds;
    for (const glm::vec3& p : pts) bounds.min = glm::min(bounds.min, p), bounds.max = glm::max(bounds.max, p);
    const glm::vec3 d = r.unit();
    const glm::mat4 lv = light_view(d, light_up(d));
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : pts) {
      const glm::vec3 q(lv * glm::vec4(p, 1.0f));
      lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
    for (int k = 0; k < 2000; ++k) {
      const glm::vec3 p = point_in_slice(corners, r);
      if (!in_box(p, box)) continue;
      ++checked;
      ASSERT_FALSE(pts.empty());
      const float tol = 1e-3f * (1.0f + glm::length(p));
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(p, bounds.min - tol)) && glm::all(glm::lessThanEqual(p, bounds.max + tol)));
      const glm::vec3 q(lv * glm::vec4(p, 1.0f));
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(q, lo - tol)) && glm::all(glm::lessThanEqual(q, hi + tol)));
    }
  }
  EXPECT_GT(checked, 2000);
}

// Each slice's map holds every receiver point of its slice, and every caster point that lies between such a
// receiver and the light, inside its clip volume (|x|, |y| ≤ w; z ≥ −w: not cut off before the near plane).
void expect_crops_hold_slices(const CascadeSettings& s, uint32_t seed) {
  Rng r(seed);
  for (int trial = 0; trial < 30; ++trial) {
    PlanInputs in;
    in.camera = random_camera(r);
    const glm::vec3 c(r.uniform(-6, 6), 0.0f, r.uniform(-6, 6));
    in.scene_receivers = Box{c - glm::vec3(r.uniform(4, 20), 0.1f, r.uniform(4, 20)),
                             c + glm::vec3(r.uniform(4, 20), r.uniform(0.5f, 4), r.uniform(4, 20))};
    in.casters = in.scene_receivers;
    in.casters.max.y += r.uniform(0, 5);
    in.receivers = camera_receiver_box(in.camera.proj * in.camera.view, in.scene_receivers);
    if (in.receivers.empty()) continue;
    LightDesc light;
    light.direction = r.unit();
    if (light.direction.y > -0.1f) light.direction.y = -light.direction.y - 0.1f;
    light.direction = glm::normalize(light.direction);
    const CascadePlan plan = plan_cascade_fits(light, s, 1024, in);
    ASSERT_EQ(plan.fits.size(), size_t(s.count));
    for (int k = 0; k < s.count; ++k) {
      const auto corners = slice_corners(in.camera, plan.splits[size_t(k)], plan.splits[size_t(k) + 1]);
      const FittedMap& m = plan.fits[size_t(k)];
      for (int i = 0; i < 400; ++i) {
        const glm::vec3 p = point_in_slice(corners, r);
        if (!in_box(p, in.scene_receivers)) continue;
        const float tol = 1e-3f;
        glm::vec4 q = clip_of(m, p);
        ASSERT_GT(q.w, 0.0f);
        ASSERT_LE(std::abs(q.x), q.w * (1 + tol)) << "slice " << k;
        ASSERT_LE(std::abs(q.y), q.w * (1 + tol)) << "slice " << k;
        ASSERT_LE(std::abs(q.z), q.w * (1 + tol)) << "slice " << k;
        // Casters towards the light from p, inside the casters' bounds.
        for (float t = 0.25f; t < 40.0f; t *= 1.6f) {
          const glm::vec3 o = p - light.direction * t;
          if (!in_box(o, in.casters)) continue;
          q = clip_of(m, o);
          ASSERT_GT(q.w, 0.0f);
          ASSERT_LE(std::abs(q.x), q.w * (1 + tol));
          ASSERT_LE(std::abs(q.y), q.w * (1 + tol));
          ASSERT_GE(q.z, -q.w * (1 + tol)) << "caster cut off by slice " << k << "'s near plane";
        }
      }
    }
  }
}

TEST(CascadeFit, TightCropsHoldTheirReceiversAndCasters) { expect_crops_hold_slices(CascadeSettings{}, 11); }
TEST(CascadeFit, StabilisedCropsHoldTheirReceiversAndCasters) {
  CascadeSettings s;
  s.stabilize = true;
  expect_crops_hold_slices(s, 12);
}
TEST(CascadeFit, LispsmCropsHoldTheirReceiversAndCasters) {
  CascadeSettings s;
  s.lispsm = true;
  expect_crops_hold_slices(s, 13);
  s.count = 1;
  expect_crops_hold_slices(s, 14);
}

TEST(CascadeFit, TightCropsAreSmallerNearTheViewer) {
  PlanInputs in;
  in.camera = make_camera({0, 2, 10}, {0, -0.2f, -1}, 50, 16.0f / 9.0f, 0.1f, 100);
  in.scene_receivers = Box{{-50, 0, -50}, {50, 1, 50}};
  in.casters = in.scene_receivers;
  in.receivers = camera_receiver_box(in.camera.proj * in.camera.view, in.scene_receivers);
  LightDesc light;
  light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const CascadePlan plan = plan_cascade_fits(light, CascadeSettings{}, 1024, in);
  // The map's width in world units is 2 / (its x scale): each slice's is larger than the one before.
  for (size_t k = 1; k < plan.fits.size(); ++k)
    EXPECT_LT(plan.fits[k].proj[0][0], plan.fits[k - 1].proj[0][0]) << "slice " << k;
}

TEST(Lispsm, DegeneratesToTheUniformMapWhenTheViewLooksAlongTheLight) {
  const CameraView cam = make_camera({0, 5, 0}, {0, -1, 0.0f}, 60, 1.0f, 0.1f, 50);
  const auto corners = slice_corners(cam, 0.1f, 50.0f);
  const Box casters{{-30, 0, -30}, {30, 2, 30}};
  for (const glm::vec3 d : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0)}) {
    const FittedMap w = fit_lispsm(d, corners, casters, cam, 0.1f, 50.0f);
    const FittedMap u = fit_ortho(d, corners, casters);
    EXPECT_FALSE(w.perspective);
    EXPECT_EQ(w.view, u.view);
    EXPECT_EQ(w.proj, u.proj);
  }
  // Off the degenerate direction the warp is there, and it weakens (n_opt grows) as the angle closes.
  const FittedMap a = fit_lispsm(glm::normalize(glm::vec3(1, -1, 0)), corners, casters, cam, 0.1f, 50.0f);
  const FittedMap b = fit_lispsm(glm::normalize(glm::vec3(0.01f, -1, 0)), corners, casters, cam, 0.1f, 50.0f);
  EXPECT_TRUE(a.perspective);
  EXPECT_TRUE(b.perspective);
  EXPECT_NEAR(a.n_opt, (0.1f + std::sqrt(0.1f * 50.0f)) / std::sin(glm::radians(45.0f)), 1e-3f);
  EXPECT_GT(b.n_opt, 50.0f * a.n_opt);
}

// The light-facing faces tile the frustum as the light sees it: every point of the frustum is owned by a face
// whose square holds it (no gaps), and no point lies strictly inside two squares (overlaps only on boundaries).
void expect_faces_tile(const CameraView& cam, glm::vec3 d, Rng& r, FaceWarp warp) {
  const Box casters{{-100, -10, -100}, {100, 20, 100}};
  const FacePlan plan = plan_face_maps(d, cam, ViewRange{cam.near, cam.far}, casters, 1024, warp);
  ASSERT_GE(plan.faces.size(), 1u);
  ASSERT_LE(plan.faces.size(), 5u);
  const auto corners = slice_corners(cam, cam.near, cam.far);
  for (int i = 0; i < 3000; ++i) {
    const glm::vec3 p = point_in_slice(corners, r);
    float margin = 0.0f;
    const size_t owner = face_owner(plan, p, &margin);
    ASSERT_GE(margin, -1e-4f) << "gap: point " << i << " lies in no face's square";
    int inside = 0;
    for (const FaceMap& f : plan.faces) {
      const glm::vec4 h = f.owner * glm::vec4(p, 1.0f);
      const float s = h.x / h.w, t = h.y / h.w;
      if (warp == FaceWarp::exact && h.w > 0 && s > 1e-3f && s < 1 - 1e-3f && t > 1e-3f && t < 1 - 1e-3f) ++inside;
    }
    if (warp == FaceWarp::exact) {
      ASSERT_LE(inside, 1) << "overlap inside two faces";
    }
    // The owner's map holds the point and every caster towards the light from it.
    const FittedMap& m = plan.faces[owner].fit;
    const glm::vec4 q = clip_of(m, p);
    ASSERT_GT(q.w, 0.0f);
    ASSERT_LE(std::abs(q.x), q.w * 1.0001f);
    ASSERT_LE(std::abs(q.y), q.w * 1.0001f);
    ASSERT_LE(std::abs(q.z), q.w * 1.0001f) << plan.faces[owner].label;
    const glm::vec4 o = clip_of(m, p - d * 5.0f);
    if (in_box(p - d * 5.0f, casters)) {
      ASSERT_GE(o.z, -o.w * 1.0001f);
    }
  }
}

TEST(FrustumFaces, TileTheFrustumForRandomViewsAndLights) {
  Rng r(21);
  for (int trial = 0; trial < 40; ++trial) {
    const CameraView cam = random_camera(r);
    expect_faces_tile(cam, r.unit(), r, FaceWarp::exact);
    expect_faces_tile(cam, r.unit(), r, FaceWarp::lispsm);
  }
}

TEST(FrustumFaces, LightBehindTheViewerAndAlongTheView) {
  Rng r(22);
  const CameraView cam = make_camera({1, 2, 3}, {0.2f, -0.3f, -1}, 60, 1.5f, 0.1f, 40);
  // Behind the viewer, shining along the view: the near face and all four sides face the light.
  const FacePlan behind = plan_face_maps(cam.forward, cam, ViewRange{cam.near, cam.far}, Box{}, 1024, FaceWarp::exact);
  EXPECT_EQ(behind.faces.size(), 5u);
  expect_faces_tile(cam, cam.forward, r, FaceWarp::exact);
  // Facing the viewer (duelling frusta): only the far face.
  const FacePlan facing = plan_face_maps(-cam.forward, cam, ViewRange{cam.near, cam.far}, Box{}, 1024, FaceWarp::exact);
  ASSERT_EQ(facing.faces.size(), 1u);
  EXPECT_EQ(facing.faces[0].label, "far");
  expect_faces_tile(cam, -cam.forward, r, FaceWarp::exact);
  // Overhead, perpendicular to the view: one side face (the top) covers the whole frustum, warped like a PSM.
  const CameraView level = make_camera({0, 2, 0}, {0, 0, -1}, 60, 1.5f, 0.1f, 40);
  const FacePlan overhead = plan_face_maps({0, -1, 0}, level, ViewRange{0.1f, 40.0f}, Box{}, 1024, FaceWarp::exact);
  ASSERT_EQ(overhead.faces.size(), 1u);
  EXPECT_EQ(overhead.faces[0].label, "top");
  expect_faces_tile(level, {0, -1, 0}, r, FaceWarp::exact);
}

}  // namespace
