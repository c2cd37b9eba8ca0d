// The tutorial's automatic light frustum (shading/techniques/tutorial_fit.h): its potential receivers and
// casters equal a brute-force classification of random object layouts (every corner through the camera's clip
// space, every corner projected on the light's axes by hand); a caster outside the view frustum but between the
// receivers and the light is in the caster set and its shadow appears in the frame; the box smoothed over a
// sequence grows at once and shrinks gradually.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/frame/frame.h"
#include "scenes/scene_build.h"
#include "scenes/scene_json.h"
#include "scenes/scene_queries.h"
#include "shading/techniques/tutorial_fit.h"
#include "tests/support.h"

namespace {

namespace tech = shading::tech;

std::array<glm::vec3, 8> corners(const tech::Box& b) {
  std::array<glm::vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[size_t(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  return c;
}

// Brute force: outside the view frustum when all eight corners are outside one clip plane.
bool brute_in_frustum(const glm::mat4& view_proj, const tech::Box& b) {
  std::array<glm::vec4, 8> clip;
  for (size_t i = 0; i < 8; ++i) clip[i] = view_proj * glm::vec4(corners(b)[i], 1.0f);
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f})
      if (std::all_of(clip.begin(), clip.end(), [&](const glm::vec4& c) { return sign * c[axis] > c.w; }))
        return false;
  return true;
}

// Brute force: the light's axes as lookAt builds them (s = d × up, u = s × d, and −d), each corner projected.
struct Interval {
  float lo = 1e30f, hi = -1e30f;
};
std::array<Interval, 3> on_light_axes(glm::vec3 direction, const tech::Box& b) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 s = glm::normalize(glm::cross(d, tech::light_up(d)));
  const glm::vec3 axes[3] = {s, glm::cross(s, d), -d};
  std::array<Interval, 3> r;
  for (const glm::vec3& c : corners(b))
    for (int a = 0; a < 3; ++a)
      r[size_t(a)].lo = std::min(r[size_t(a)].lo, glm::dot(axes[a], c)),
      r[size_t(a)].hi = std::max(r[size_t(a)].hi, glm::dot(axes[a], c));
  return r;
}

struct Layout {
  std::vector<tech::ObjectBounds> objects;
  tech::TutorialFitInput in;
};

Layout random_layout(std::mt19937& rng) {
  std::uniform_real_distribution<float> pos(-30.0f, 30.0f), size(0.1f, 6.0f), unit(-1.0f, 1.0f), u01(0.0f, 1.0f);
  Layout l;
  const int n = 20 + int(rng() % 60);
  for (int i = 0; i < n; ++i) {
    const glm::vec3 c(pos(rng), pos(rng) * 0.5f, pos(rng)), h(size(rng), size(rng), size(rng));
    tech::ObjectBounds o;
    o.box = tech::Box{c - h, c + h};
    o.caster = u01(rng) < 0.8f;
    o.receiver = u01(rng) < 0.8f;
    l.objects.push_back(o);
    l.in.scene.min = glm::min(l.in.scene.min, o.box.min);
    l.in.scene.max = glm::max(l.in.scene.max, o.box.max);
  }
  // Sometimes a scene box smaller than the objects, so the scene-box test matters.
  if (u01(rng) < 0.3f) l.in.scene = tech::Box{glm::vec3(-20.0f), glm::vec3(20.0f)};
  l.in.direction = glm::normalize(glm::vec3(unit(rng), -0.2f - u01(rng), unit(rng)));
  l.in.eye = glm::vec3(pos(rng), 5.0f + 10.0f * u01(rng), pos(rng));
  const glm::vec3 target(pos(rng) * 0.3f, 0.0f, pos(rng) * 0.3f);
  l.in.forward = glm::normalize(target - l.in.eye);
  const float far = 20.0f + 60.0f * u01(rng);
  l.in.camera_view_proj = glm::perspective(glm::radians(30.0f + 40.0f * u01(rng)), 1.0f + u01(rng), 0.1f, far) *
                          glm::lookAt(l.in.eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
  l.in.cutoff = u01(rng) < 0.5f ? far : 5.0f + (far - 5.0f) * u01(rng);
  return l;
}

tech::TutorialSets brute_sets(const Layout& l) {
  tech::TutorialSets s;
  for (size_t i = 0; i < l.objects.size(); ++i) {
    const tech::Box& b = l.objects[i].box;
    float nearest = 1e30f;
    for (const glm::vec3& c : corners(b)) nearest = std::min(nearest, glm::dot(c - l.in.eye, l.in.forward));
    const bool in_scene = b.min.x <= l.in.scene.max.x && l.in.scene.min.x <= b.max.x &&
                          b.min.y <= l.in.scene.max.y && l.in.scene.min.y <= b.max.y &&
                          b.min.z <= l.in.scene.max.z && l.in.scene.min.z <= b.max.z;
    if (l.objects[i].receiver && brute_in_frustum(l.in.camera_view_proj, b) && in_scene && nearest <= l.in.cutoff) {
      s.receivers.push_back(i);
      s.receiver_box.min = glm::min(s.receiver_box.min, b.min);
      s.receiver_box.max = glm::max(s.receiver_box.max, b.max);
    }
  }
  if (s.receivers.empty()) return s;
  const std::array<Interval, 3> r = on_light_axes(l.in.direction, s.receiver_box);
  for (size_t i = 0; i < l.objects.size(); ++i) {
    const bool receiver = std::find(s.receivers.begin(), s.receivers.end(), i) != s.receivers.end();
    const std::array<Interval, 3> o = on_light_axes(l.in.direction, l.objects[i].box);
    const bool between = o[0].lo <= r[0].hi && r[0].lo <= o[0].hi && o[1].lo <= r[1].hi && r[1].lo <= o[1].hi &&
                         o[2].hi >= r[2].lo;
    if (receiver || (l.objects[i].caster && between)) s.casters.push_back(i);
  }
  return s;
}

}  // namespace

TEST(TutorialFit, SetsEqualBruteForceOnRandomLayouts) {
  std::mt19937 rng(22);
  size_t receivers = 0, extra_casters = 0, dropped = 0, total = 0;
  for (int k = 0; k < 400; ++k) {
    const Layout l = random_layout(rng);
    const tech::TutorialSets got = tech::tutorial_sets(l.objects, l.in);
    const tech::TutorialSets want = brute_sets(l);
    ASSERT_EQ(got.receivers, want.receivers) << "layout " << k;
    ASSERT_EQ(got.casters, want.casters) << "layout " << k;
    if (!want.receivers.empty()) {
      EXPECT_EQ(got.receiver_box.min, want.receiver_box.min);
      EXPECT_EQ(got.receiver_box.max, want.receiver_box.max);
    }
    receivers += want.receivers.size();
    extra_casters += want.casters.size() - want.receivers.size();
    total += l.objects.size();
    dropped += l.objects.size() - want.casters.size();
  }
  // Not degenerate: objects of every kind occur in quantity.
  EXPECT_GT(receivers, total / 10);
  EXPECT_GT(extra_casters, total / 20);
  EXPECT_GT(dropped, total / 10);
}

// The final box holds every caster's box in the light's frame, and the matrices map them into the clip volume.
TEST(TutorialFit, FinalBoxHoldsEveryCaster) {
  std::mt19937 rng(7);
  for (int k = 0; k < 100; ++k) {
    const Layout l = random_layout(rng);
    const tech::TutorialSets sets = tech::tutorial_sets(l.objects, l.in);
    const tech::LightMatrices m = tech::light_box_matrices(tech::tutorial_light_box(l.objects, sets, l.in));
    for (size_t i : sets.casters)
      for (const glm::vec3& c : corners(l.objects[i].box)) {
        const glm::vec4 ndc = m.proj * m.view * glm::vec4(c, 1.0f);
        ASSERT_LE(std::abs(ndc.x), 1.0f) << "layout " << k << " object " << i;
        ASSERT_LE(std::abs(ndc.y), 1.0f);
        ASSERT_LE(std::abs(ndc.z), 1.0f);
      }
  }
}

TEST(TutorialFit, SmoothingGrowsAtOnceAndShrinksGradually) {
  const glm::vec3 d = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
  const tech::LightBox prev{d, glm::vec3(-10.0f), glm::vec3(10.0f)};
  const tech::LightBox smaller{d, glm::vec3(-2.0f), glm::vec3(2.0f)};
  const tech::LightBox s = tech::smooth_light_box(smaller, prev, 0.75f);
  EXPECT_EQ(s.lo, glm::vec3(-8.0f));  // a quarter of the way from -10 to -2
  EXPECT_EQ(s.hi, glm::vec3(8.0f));
  const tech::LightBox larger{d, glm::vec3(-20.0f, -5.0f, -5.0f), glm::vec3(5.0f, 20.0f, 5.0f)};
  const tech::LightBox g = tech::smooth_light_box(larger, prev, 0.75f);
  EXPECT_EQ(g.lo, glm::vec3(-20.0f, -8.75f, -8.75f));  // grew at once on x; shrinks towards -5 on y, z
  EXPECT_EQ(g.hi, glm::vec3(8.75f, 20.0f, 8.75f));
  EXPECT_EQ(tech::smooth_light_box(smaller, std::nullopt, 0.75f).lo, smaller.lo);
  EXPECT_EQ(tech::smooth_light_box(smaller, prev, 0.0f).lo, smaller.lo);
  const tech::LightBox turned{glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)), smaller.lo, smaller.hi};
  EXPECT_EQ(tech::smooth_light_box(turned, prev, 0.75f).lo, smaller.lo);  // the light turned: no history
}

namespace {

// A floor the camera looks at, a box high above and behind the camera's view (between the floor and the sun,
// outside the view frustum) and a second box as high but far to the side (between nothing and the sun).
const char* kHiddenCaster = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [16, 16]}, "casts_shadows": false},
    {"name": "hidden", "primitive": {"type": "box", "size": [3, 3, 3]}, "transform": {"translate": [0, 20, -20]}},
    {"name": "aside", "primitive": {"type": "box", "size": [3, 3, 3]}, "transform": {"translate": [60, 20, -20]}}
  ],
  "cameras": [{"position": [0, 10, 10], "target": [0, 0, 0], "perspective": {"fovy": 45, "near": 0.5, "far": 60}}],
  "lights": [{"type": "directional", "direction": [0, -1, 1],
              "shadow": {"technique": "shadowmap", "filter": "hard", "map_size": 512, "params": {"fit": "tutorial"}}}]
})";

scenes::Scene scene_from(const std::string& json) {
  return scenes::build_scene(scenes::parse_scene_json(json, "test.json"));
}

// Mean of the red channel over the frame's centre square.
double centre_brightness(const raster::ColorTarget& c) {
  double sum = 0.0;
  int n = 0;
  for (int y = c.height() / 2 - 8; y < c.height() / 2 + 8; ++y)
    for (int x = c.width() / 2 - 8; x < c.width() / 2 + 8; ++x, ++n) sum += c.row8(y)[4 * x];
  return sum / n;
}

}  // namespace

TEST(TutorialFit, HiddenCasterBetweenReceiversAndLightCastsItsShadow) {
  const scenes::Scene scene = scene_from(kHiddenCaster);
  ASSERT_EQ(scene.instances.size(), 3u);
  // The sets, as the frame builds them.
  std::vector<tech::ObjectBounds> objects;
  tech::TutorialFitInput in;
  for (size_t k = 0; k < scene.instances.size(); ++k) {
    const scenes::Aabb b = scenes::instance_bounds(scene, k);
    objects.push_back({tech::Box{b.min, b.max}, scene.instances[k].casts_shadows, scene.instances[k].receives_shadows});
  }
  const scenes::Aabb all = scenes::scene_bounds(scene);
  in.scene = tech::Box{all.min, all.max};
  in.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
  in.eye = glm::vec3(0.0f, 10.0f, 10.0f);
  in.forward = glm::normalize(-in.eye);
  in.camera_view_proj = glm::perspective(glm::radians(45.0f), 16.0f / 9.0f, 0.5f, 60.0f) *
                        glm::lookAt(in.eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  in.cutoff = 60.0f;
  EXPECT_FALSE(tech::box_in_frustum(in.camera_view_proj, objects[1].box));  // the hidden box is out of view
  const tech::TutorialSets sets = tech::tutorial_sets(objects, in);
  EXPECT_EQ(sets.receivers, std::vector<size_t>({0}));
  EXPECT_EQ(sets.casters, std::vector<size_t>({0, 1}));

  // Its shadow falls on the middle of the view: the frame is darker there than without it.
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig o;
  o.width = 160, o.height = 90;
  const frame::Frame with = frame::render_frame(scene, o, renderer);
  scenes::Scene without = scene;
  without.instances[1].casts_shadows = false;
  const frame::Frame lit = frame::render_frame(without, o, renderer);
  EXPECT_LT(centre_brightness(with.color), 0.7 * centre_brightness(lit.color));
  // The same at other thread counts, bit for bit.
  for (int threads : {0, 1, 2, 7}) {
    raster::Renderer r(threads);
    const frame::Frame again = frame::render_frame(scene, o, r);
    for (int y = 0; y < o.height; ++y)
      ASSERT_TRUE(std::equal(again.color.row8(y), again.color.row8(y) + 4 * o.width, with.color.row8(y)))
          << threads << " threads, row " << y;
  }
}

// Across the frames of one sequence (one FrameCache), the light's box is kept and smoothed; without a cache a
// frame stands alone.
TEST(TutorialFit, SequenceKeepsTheBoxInTheCache) {
  scenes::Scene scene = scene_from(kHiddenCaster);
  raster::Renderer renderer(0);
  frame::FrameConfig o;
  o.width = 64, o.height = 36;
  frame::FrameCache cache;
  frame::render_frame(scene, o, renderer, &cache);
  ASSERT_TRUE(cache.fits[0].box.has_value());
  const tech::LightBox first = *cache.fits[0].box;
  scene.instances[1].casts_shadows = false;  // the hidden caster leaves: the box would shrink at once
  frame::render_frame(scene, o, renderer, &cache);
  const tech::LightBox second = *cache.fits[0].box;
  frame::FrameCache fresh;
  frame::render_frame(scene, o, renderer, &fresh);
  const tech::LightBox alone = *fresh.fits[0].box;
  EXPECT_GT(second.hi.z, alone.hi.z);  // still reaching towards where the caster was
  EXPECT_LT(second.hi.z, first.hi.z);  // but on its way down
}

TEST(TutorialFit, ParametersOfTheTutorialFitAreRefusedForOtherFits) {
  const scenes::Scene scene = scene_from(kHiddenCaster);
  raster::Renderer renderer(0);
  frame::FrameConfig o;
  o.width = 32, o.height = 18;
  o.params["fit"] = std::string("auto");
  o.params["fit_cutoff"] = 10.0;
  try {
    frame::render_frame(scene, o, renderer);
    FAIL() << "no error";
  } catch (const frame::FrameError& e) {
    EXPECT_NE(std::string(e.what()).find("fit_cutoff: applies to fit = tutorial only"), std::string::npos) << e.what();
  }
}
