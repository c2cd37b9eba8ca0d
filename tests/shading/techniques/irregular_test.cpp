// The irregular z-buffer (shading/techniques/irregular*.h): one triangle over a plane under a directional and a
// spot light, every sample's answer known in closed form, samples on the triangle's edges and corners included;
// the grid against a brute-force test of every triangle with every sample, with the over-full-cell fallback
// forced, at 0, 1, 2 and 7 threads; whole frames against the ray-cast reference; antialiased samples.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/frame/frame.h"
#include "scenes/reference/frame_reference.h"
#include "shading/techniques/irregular.h"
#include "shading/techniques/irregular_ray.h"
#include "tests/scenes/frame/golden.h"
#include "tests/scenes/reference/analytic_scenes.h"
#include "tests/support.h"

namespace {

namespace tech = shading::tech;

// The triangle (0, h, 0), (1, h, 0), (0, h, 1): its closed shadow straight down is x >= 0, z >= 0, x + z <= 1.
struct OneTriangle {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices{0, 1, 2};
  explicit OneTriangle(float h) : positions{{0.0f, h, 0.0f}, {1.0f, h, 0.0f}, {0.0f, h, 1.0f}} {}
  tech::CasterGeometry geometry() const { return {positions, indices}; }
};

bool in_closed_triangle(double x, double z) { return x >= 0.0 && z >= 0.0 && x + z <= 1.0; }
bool on_boundary(double x, double z) {
  return in_closed_triangle(x, z) && (x == 0.0 || z == 0.0 || x + z == 1.0);
}

// Samples on y = 0 every 1/16 m over [-0.5, 1.5]²: many lie exactly on the triangle's edges and corners.
std::vector<glm::vec3> floor_samples() {
  std::vector<glm::vec3> s;
  for (int i = -8; i <= 24; ++i)
    for (int k = -8; k <= 24; ++k) s.emplace_back(float(i) / 16.0f, 0.0f, float(k) / 16.0f);
  return s;
}

tech::LightDesc sun_straight_down() {
  tech::LightDesc l;
  l.type = tech::LightType::directional;
  l.direction = {0.0f, -1.0f, 0.0f};
  return l;
}

TEST(IrregularRay, TheTriangleIsClosedAndBlocksOnlyInFrontOfTheOrigin) {
  const glm::dvec3 a(0, 1, 0), b(1, 1, 0), c(0, 1, 1);
  auto up_from = [](double x, double y, double z) {
    return tech::ShadowRay{{x, y, z}, {0.0, 1.0, 0.0}, std::numeric_limits<double>::infinity()};
  };
  EXPECT_TRUE(tech::blocks(a, b, c, up_from(0.25, 0.0, 0.25)));   // inside
  EXPECT_TRUE(tech::blocks(a, b, c, up_from(0.5, 0.0, 0.0)));     // on an edge
  EXPECT_TRUE(tech::blocks(a, b, c, up_from(0.5, 0.0, 0.5)));     // on the hypotenuse
  EXPECT_TRUE(tech::blocks(a, b, c, up_from(1.0, 0.0, 0.0)));     // on a corner
  EXPECT_FALSE(tech::blocks(a, b, c, up_from(0.5, 0.0, 0.5000001)));  // just outside
  EXPECT_FALSE(tech::blocks(a, b, c, up_from(0.25, 1.0, 0.25)));  // in the triangle's plane: it never shadows itself
  EXPECT_FALSE(tech::blocks(a, b, c, up_from(0.25, 2.0, 0.25)));  // above it
  // A ray in the triangle's plane passes no inside, even through it.
  EXPECT_FALSE(tech::blocks(a, b, c, tech::ShadowRay{{-1.0, 1.0, 0.25}, {1.0, 0.0, 0.0}, 1e9}));
  // Segments to a spot light stop before the light: an occluder beyond it does not count.
  EXPECT_FALSE(tech::blocks(a, b, c, tech::ShadowRay{{0.25, 0.0, 0.25}, {0.0, 0.5, 0.0}, 1.0 - 1e-5}));
  EXPECT_TRUE(tech::blocks(a, b, c, tech::ShadowRay{{0.25, 0.0, 0.25}, {0.0, 2.0, 0.0}, 1.0 - 1e-5}));
}

TEST(IrregularGrid, OneTriangleOverAPlaneUnderTheSunAgreesExactly) {
  const OneTriangle tri(1.0f);
  const std::vector<glm::vec3> samples = floor_samples();
  raster::ThreadPool pool(testsupport::test_threads());
  tech::GridStats stats;
  const std::vector<uint8_t> shadowed = tech::irregular_shadow(tech::irregular_light(sun_straight_down()), samples,
                                                               tri.geometry(), tech::GridSettings{}, pool, stats);
  size_t edges = 0, inside = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const double x = samples[i].x, z = samples[i].z;
    EXPECT_EQ(bool(shadowed[i]), in_closed_triangle(x, z)) << "sample at x " << x << ", z " << z;
    edges += on_boundary(x, z), inside += in_closed_triangle(x, z);
  }
  EXPECT_EQ(edges, 48u);   // 16 samples on each edge, corners once
  EXPECT_EQ(inside, 153u);  // 17 · 18 / 2
  EXPECT_EQ(stats.samples, samples.size());
  EXPECT_GT(stats.tests, 0u);
}

// A spot at (0.25, 4, 0.25) pointing down, the triangle at y = 2: a floor point p is shadowed when the segment
// to the light meets y = 2 at ((0.25 + x) / 2, (0.25 + z) / 2) inside the closed triangle.
TEST(IrregularGrid, OneTriangleOverAPlaneUnderASpotAgreesExactly) {
  const OneTriangle tri(2.0f);
  std::vector<glm::vec3> samples = floor_samples();
  samples.emplace_back(0.25f, 2.0f, 0.25f);  // in the triangle itself: it never shadows itself
  samples.emplace_back(0.25f, 3.0f, 0.25f);  // between the triangle and the light
  tech::LightDesc spot;
  spot.type = tech::LightType::spot;
  spot.position = {0.25f, 4.0f, 0.25f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  raster::ThreadPool pool(testsupport::test_threads());
  tech::GridStats stats;
  const std::vector<uint8_t> shadowed =
      tech::irregular_shadow(tech::irregular_light(spot), samples, tri.geometry(), tech::GridSettings{}, pool, stats);
  size_t edges = 0;
  for (size_t i = 0; i + 2 < samples.size(); ++i) {
    const double qx = (0.25 + samples[i].x) / 2.0, qz = (0.25 + samples[i].z) / 2.0;
    EXPECT_EQ(bool(shadowed[i]), in_closed_triangle(qx, qz)) << "sample at x " << samples[i].x << ", z " << samples[i].z;
    edges += on_boundary(qx, qz);
  }
  EXPECT_GT(edges, 20u);
  EXPECT_FALSE(shadowed[samples.size() - 2]);
  EXPECT_FALSE(shadowed[samples.size() - 1]);
}

// Random triangles over random samples and a dense patch of them: the grid (conservative rasterization over both
// levels of cells, per-cell lists, the key cull) must give exactly what testing every triangle against every
// sample gives, with the default cell bound (the patch's top cells split) and with a bound of 1 and a cap of 8
// cells a side so that over-full cells take the fallback, at any thread count.
TEST(IrregularGrid, AgreesWithEveryTriangleAgainstEverySampleAtAnyThreadCount) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f), h(0.2f, 3.0f);
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  for (int t = 0; t < 300; ++t) {
    const glm::vec3 c(u(rng), h(rng), u(rng));
    for (int k = 0; k < 3; ++k) {
      indices.push_back(uint32_t(positions.size()));
      positions.push_back(c + 0.3f * glm::vec3(u(rng), u(rng), u(rng)));
    }
  }
  std::vector<glm::vec3> samples;
  for (int i = 0; i < 4000; ++i) samples.emplace_back(1.5f * u(rng), 0.5f * h(rng) - 0.1f, 1.5f * u(rng));
  // And a dense patch 5 cm wide, as a grazing floor crowds the light's view: its top cells split.
  for (int i = 0; i < 3000; ++i)
    samples.emplace_back(0.2f + 0.0125f * u(rng), 0.5f * h(rng) - 0.1f, -0.3f + 0.0125f * u(rng));
  const tech::CasterGeometry casters{positions, indices};
  for (const tech::LightDesc& light : {sun_straight_down(), [] {
         tech::LightDesc l;
         l.type = tech::LightType::spot;
         l.position = {0.3f, 6.0f, -0.2f};
         l.direction = glm::normalize(glm::vec3(0.05f, -1.0f, 0.02f));
         return l;
       }()}) {
    const tech::IrregularLight il = tech::irregular_light(light);
    std::vector<uint8_t> brute(samples.size(), 0);
    for (size_t s = 0; s < samples.size(); ++s) {
      tech::ShadowRay r;
      r.origin = glm::dvec3(samples[s]);
      r.dir = il.spot ? il.position - r.origin : -il.axis;
      r.t_max = il.spot ? 1.0 - 1e-5 : std::numeric_limits<double>::infinity();
      for (size_t t = 0; t < indices.size() / 3 && !brute[s]; ++t)
        brute[s] = tech::blocks(glm::dvec3(positions[indices[3 * t]]), glm::dvec3(positions[indices[3 * t + 1]]),
                                glm::dvec3(positions[indices[3 * t + 2]]), r);
    }
    const size_t shadowed = size_t(std::count(brute.begin(), brute.end(), 1));
    EXPECT_GT(shadowed, 500u);
    EXPECT_LT(shadowed, samples.size() - 500u);
    for (const tech::GridSettings settings : {tech::GridSettings{}, tech::GridSettings{1, 8}})
      for (int threads : {0, 1, 2, 7}) {
        SCOPED_TRACE(std::string(il.spot ? "spot" : "sun") + ", cell bound " + std::to_string(settings.cell_bound) +
                     ", " + std::to_string(threads) + " threads");
        raster::ThreadPool pool(threads);
        tech::GridStats stats;
        EXPECT_EQ(tech::irregular_shadow(il, samples, casters, settings, pool, stats), brute);
        if (settings.max_side == 8) {
          EXPECT_EQ(stats.cells_x, 8u);
          EXPECT_GT(stats.overfull_samples, 0u);  // the fallback ran: over-full cells, tested all the same
        } else {
          EXPECT_GT(stats.split_cells, 0u);  // the patch's cells have grids of their own
          EXPECT_LE(stats.max_in_cell, size_t(settings.cell_bound));
        }
      }
  }
}

frame::FrameConfig irregular_view(int samples = 1, int w = 320, int h = 240) {
  frame::FrameConfig c;
  c.width = w, c.height = h;
  c.technique = tech::Technique::irregular;
  c.params["samples_per_pixel"] = double(samples);
  return c;
}

// The square over the floor under the sun, and the same square under a spot: every lit-facing pixel agrees with
// the ray-cast reference, near edges too, with no bias setting.
// The light-space pass works in bands of rows when a frame holds more samples than one batch may: a batch of 100
// samples (one row of 64 pixels at a time) gives every pixel the same visibility as one batch of all of them,
// at one and eight samples a pixel, and with one sample the closed form of the triangle's shadow.
TEST(IrregularVisibility, BandsOfRowsGiveTheSameAnswerAsOneBatch) {
  constexpr int kSide = 64;
  tech::CameraSurface surface;
  surface.width = surface.height = kSide;
  surface.covered.assign(size_t(kSide) * kSide, 1);
  surface.normal.assign(surface.covered.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  surface.position.resize(surface.covered.size());
  surface.epsilon = 1e-4f;
  for (int y = 0; y < kSide; ++y)  // 1/32 m a pixel over [-0.5, 1.5]², x along columns, z along rows
    for (int x = 0; x < kSide; ++x)
      surface.position[surface.index(x, y)] = {(float(x) + 0.5f) / 32.0f - 0.5f, 0.0f, (float(y) + 0.5f) / 32.0f - 0.5f};
  // A camera straight above the square, so the footprints of the sub-samples lie on the floor too.
  const glm::mat4 view_proj(glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec4(0.0f, 0.0f, -0.1f, 0.0f),
                            glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), glm::vec4(-0.5f, -0.5f, 0.5f, 1.0f));
  const OneTriangle tri(1.0f);
  raster::ThreadPool pool(testsupport::test_threads());
  for (int spp : {1, 8}) {
    tech::IrregularSettings whole, banded;
    whole.samples_per_pixel = banded.samples_per_pixel = spp;
    banded.max_batch_samples = 100;
    const tech::IrregularBuffer a =
        tech::irregular_visibility(surface, sun_straight_down(), view_proj, whole, tri.geometry(), pool);
    const tech::IrregularBuffer b =
        tech::irregular_visibility(surface, sun_straight_down(), view_proj, banded, tri.geometry(), pool);
    ASSERT_EQ(a.visibility.size(), b.visibility.size());
    size_t dark = 0;
    for (size_t p = 0; p < a.visibility.size(); ++p) {
      EXPECT_EQ(a.visibility[p], b.visibility[p]) << spp << " samples, pixel " << p;
      dark += a.visibility[p] < 1.0f;
      if (spp == 1) {
        const glm::vec3 q = surface.position[p];
        EXPECT_EQ(a.visibility[p], in_closed_triangle(q.x, q.z) ? 0.0f : 1.0f) << "pixel " << p;
      }
    }
    EXPECT_GT(dark, 400u) << spp;  // the triangle's shadow, half of a 32 x 32 square
  }
}

TEST(IrregularFrame, AgreesWithTheRayCastReference) {
  const char* kSquareUnderSpot = R"({
    "objects": [
      {"name": "floor", "primitive": {"type": "plane", "size": [8, 8]}},
      {"name": "square", "primitive": {"type": "plane", "size": [1, 1]}, "transform": {"translate": [0, 1, 0]}},
      {"name": "box", "primitive": {"type": "box", "size": [0.5, 0.5, 0.5]}, "transform": {"translate": [1, 0.25, -0.5]}}
    ],
    "cameras": [{"position": [0, 7, 2], "target": [0, 0, 0]}],
    "lights": [{"type": "spot", "position": [0.2, 3, 0.1], "direction": [0, -1, 0], "inner_cone": 30,
                "outer_cone": 40, "range": 20}]
  })";
  raster::Renderer renderer(testsupport::test_threads());
  for (const char* json : {testsupport::kSquareOverFloor, kSquareUnderSpot, testsupport::kSphereUnderPointLight}) {
    const scenes::Scene scene = testsupport::scene_from_json(json);
    const reference::FrameReference ref = reference::reference_for(scene, irregular_view(), renderer);
    const reference::ScoredFrame scored = reference::score_config(scene, irregular_view(), renderer, ref);
    const reference::LightScore& s = scored.score.lights.at(0);
    EXPECT_GT(s.scored, 20000u);
    // Both rays (the reference's and irregular's) run from the moved origin to the light itself: every pixel
    // agrees, under the sun and under the spot. (While the reference's spot ray ran parallel to the point's own
    // direction to the light, one row of 62 pixels along the square's shadow differed.)
    EXPECT_EQ(s.false_shadowed(), 0u);
    EXPECT_EQ(s.false_lit(), 0u);
    // The shadow is there: some lit-facing pixels are shadowed.
    const frame::SurfaceRecord& r = *scored.frame.surface;
    size_t dark = 0;
    for (size_t p = 0; p < r.pixels(); ++p) dark += r.lit_facing[p] && r.visibility[p] < 0.5f;
    EXPECT_GT(dark, 300u);
  }
}

TEST(IrregularFrame, SameFrameAtAnyThreadCount) {
  for (const char* json : {testsupport::kSquareOverFloor, testsupport::kSphereUnderPointLight}) {
    const scenes::Scene scene = testsupport::scene_from_json(json);
    for (int samples : {1, 8}) {
      uint64_t first = 0;
      for (int threads : {0, 1, 2, 7}) {
        raster::Renderer renderer(threads);
        const frame::Frame f = frame::render_frame(scene, irregular_view(samples), renderer);
        const uint64_t h = testsupport::frame_hash(f.color);
        if (threads == 0) first = h;
        EXPECT_EQ(h, first) << shading::tech::to_string(scene.lights[0].type) << " light, " << samples
                            << " samples per pixel, " << threads << " threads";
      }
    }
  }
}

// Eight and thirty-two samples per pixel give fractions along the shadow's edge and agree with one sample per
// pixel away from it; other counts are refused, naming the parameter.
TEST(IrregularFrame, SamplesPerPixelAntialiasTheEdge) {
  const scenes::Scene scene = testsupport::scene_from_json(testsupport::kSquareOverFloor);
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig one = irregular_view(1);
  one.surface_record = true;
  const frame::Frame f1 = frame::render_frame(scene, one, renderer);
  for (int samples : {8, 32}) {
    frame::FrameConfig many = irregular_view(samples);
    many.surface_record = true;
    const frame::Frame fn = frame::render_frame(scene, many, renderer);
    const frame::SurfaceRecord &a = *f1.surface, &b = *fn.surface;
    size_t fractional = 0, disagree = 0, lit = 0;
    for (size_t p = 0; p < a.pixels(); ++p) {
      if (!a.lit_facing[p]) continue;
      ++lit;
      const float v = b.visibility[p];
      fractional += v > 0.0f && v < 1.0f;
      disagree += (v == 0.0f || v == 1.0f) && v != a.visibility[p];
      EXPECT_EQ(std::fmod(v * float(samples), 1.0f), 0.0f);
    }
    EXPECT_GT(fractional, 40u) << samples;        // the edge is graded
    EXPECT_LT(disagree, lit / 1000) << samples;  // elsewhere the same answer
  }
  try {
    frame::render_frame(scene, irregular_view(5), renderer);
    ADD_FAILURE() << "5 samples per pixel accepted";
  } catch (const frame::FrameError& e) {
    EXPECT_NE(std::string(e.what()).find("samples_per_pixel"), std::string::npos) << e.what();
  }
}

}  // namespace
