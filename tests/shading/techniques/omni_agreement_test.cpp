// The three omnidirectional techniques against each other and against the exact answer. On a receiver plane
// under a hemispherical light, each technique's shadowed set is compared with ray casting: every disagreement
// must lie within a few of that technique's texels of an exact shadow edge (the measured worst case is printed
// and stated in docs/omnidirectional.md). On the built-in `pyramid` scene, points near the pyramid's region
// boundaries are read through the pyramid and the cube map; a difference where the cube's answer is the same
// all around (not a shadow edge) would be a seam: there must be none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_queries.h"
#include "tests/shading/techniques/omni_test_util.h"

namespace {

using namespace omnitest;

void box(techtest::Soup& s, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 a = lo, b = hi;
  s.quad({a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, a.y, b.z}, {a.x, a.y, b.z});
  s.quad({a.x, b.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z});
  s.quad({a.x, a.y, a.z}, {a.x, b.y, a.z}, {a.x, b.y, b.z}, {a.x, a.y, b.z});
  s.quad({b.x, a.y, a.z}, {b.x, b.y, a.z}, {b.x, b.y, b.z}, {b.x, a.y, b.z});
  s.quad({a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z});
  s.quad({a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z});
}

// Möller–Trumbore: does the open segment from o to o + d (t in (eps, 1 − eps)) hit triangle abc?
bool hits(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-12) return false;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = glm::dot(e2, q) * inv;
  return t > 1e-6 && t < 1.0 - 1e-6;
}

bool exact_lit(const techtest::Soup& casters, glm::vec3 p, glm::vec3 light) {
  const glm::dvec3 o(p), d = glm::dvec3(light) - glm::dvec3(p);
  for (size_t i = 0; i + 2 < casters.indices.size(); i += 3)
    if (hits(o, d, casters.positions[casters.indices[i]], casters.positions[casters.indices[i + 1]],
             casters.positions[casters.indices[i + 2]]))
      return false;
  return true;
}

// Map texel coordinates of a world point for a technique (for texel-size estimates by finite differences);
// the int is the face / hemisphere / region so that differences across a boundary can be skipped.
std::pair<int, glm::vec2> map_texel(const tech::OmniReader& r, int n, glm::vec3 p) {
  switch (r.kind) {
    case tech::OmniKind::cube: {
      const shading::CubeCoord c = shading::cube_coord(p - r.position);
      return {c.face, glm::vec2(c.s, c.t) * float(n)};
    }
    case tech::OmniKind::paraboloid: {
      const glm::vec3 P = r.frame.to_light(p);
      const tech::ParaboloidCoord c = tech::paraboloid_coord(P, P.z >= 0.0f ? 1.0f : -1.0f, 1.0f);
      return {P.z >= 0.0f ? 0 : 1, (c.xy * 0.5f + 0.5f) * float(n)};
    }
    case tech::OmniKind::pyramid: {
      const glm::vec3 P = r.frame.to_light(p);
      return {tech::pyramid_region(P.x, P.y), tech::pyramid_st(P) * float(n)};
    }
  }
  return {0, {}};
}

TEST(OmniAgreement, ReceiverPlaneMatchesRayCastingUpToAFewTexels) {
  techtest::Soup casters;  // what shadows the plane
  box(casters, {-1.2f, 0.8f, -0.4f}, {-0.2f, 1.4f, 0.6f});   // below the light, across the pyramid's seams
  box(casters, {1.5f, 0.3f, 1.2f}, {2.3f, 1.9f, 1.8f});      // a tall box off to the side
  box(casters, {-2.8f, 0.5f, -2.6f}, {-2.2f, 1.0f, -1.4f});  // under a region boundary (|x| = |z|)
  box(casters, {0.6f, 1.6f, -1.6f}, {1.4f, 1.8f, -0.9f});    // a thin slab high up
  techtest::Soup all = casters;
  all.quad({-7, 0, 7}, {7, 0, 7}, {7, 0, -7}, {-7, 0, -7});  // the receiver is in the map too

  tech::OmniLight light;
  light.position = {0.05f, 3.0f, -0.03f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.range = 15.0f;
  light.hemispherical = true;

  // Equal memory: 6 · 512² texels for the cube; the pyramid's and the (single, hemispherical) paraboloid's
  // square of 1254² holds as many.
  struct Tech {
    tech::OmniKind kind;
    int n;
    const char* name;
  };
  const Tech techs[] = {{tech::OmniKind::cube, 512, "cube"},
                        {tech::OmniKind::paraboloid, 1254, "paraboloid"},
                        {tech::OmniKind::pyramid, 1254, "pyramid"}};
  const int g = 361;  // samples per side over [−6, 6]²
  const float step = 12.0f / float(g - 1);
  std::vector<uint8_t> exact(size_t(g) * size_t(g));
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i)
      exact[size_t(j) * g + i] = exact_lit(casters, {-6.0f + step * i, 0.0f, -6.0f + step * j}, light.position);

  raster::Renderer r(2);
  for (const Tech& t : techs) {
    tech::OmniSettings s;
    s.map_size = t.n;
    s.filter = tech::FilterKind::hard;
    s.depth_format = raster::DepthFormat::d24;
    s.bias.mode = tech::BiasMode::slope;
    BuiltOmni b = build_omni(r, t.kind, all, light, s);
    int differ = 0;
    float worst_texels = 0.0f, worst_m = 0.0f;
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        const glm::vec3 p{-6.0f + step * i, 0.0f, -6.0f + step * j};
        const tech::ShadowQuery q{p, glm::vec3(0, 1, 0), glm::vec2(0.0f)};
        float v = 0.0f;
        tech::omni_visibility(b.reader, std::span(&q, 1), std::span(&v, 1));
        const bool lit = v > 0.5f;
        if (lit == bool(exact[size_t(j) * g + i])) continue;
        ++differ;
        // Distance to the nearest sample of the other exact answer, searched outwards.
        float best = 1e9f;
        glm::vec2 dir(1, 0);
        for (int rr = 1; rr <= 30 && best > float(rr - 1) * step; ++rr)
          for (int dj = -rr; dj <= rr; ++dj)
            for (int di = -rr; di <= rr; ++di) {
              if (std::max(std::abs(di), std::abs(dj)) != rr) continue;
              const int x = i + di, y = j + dj;
              if (x < 0 || y < 0 || x >= g || y >= g) continue;
              if (bool(exact[size_t(y) * g + x]) != lit) continue;
              const float d = step * std::sqrt(float(di * di + dj * dj));
              if (d < best) best = d, dir = glm::vec2(float(di), float(dj)) / std::sqrt(float(di * di + dj * dj));
            }
        // The exact edge between the point and that sample, by bisection with ray casting.
        {
          glm::vec3 lo = p, hi = p + glm::vec3(dir.x, 0.0f, dir.y) * best;
          for (int it = 0; it < 24; ++it) {
            const glm::vec3 mid = 0.5f * (lo + hi);
            (exact_lit(casters, mid, light.position) == lit ? hi : lo) = mid;
          }
          best = glm::length(0.5f * (lo + hi) - p);
        }
        // Texels per metre along that direction, by a finite difference of the map coordinates.
        const float h = 1e-3f;
        const auto a = map_texel(b.reader, t.n, p), c = map_texel(b.reader, t.n, p + glm::vec3(dir.x, 0, dir.y) * h);
        const float per_m = a.first == c.first ? glm::length(c.second - a.second) / h : 0.0f;
        worst_m = std::max(worst_m, best);
        worst_texels = std::max(worst_texels, best * per_m);
      }
    std::printf("agreement %s (%d²): %d of %d plane samples differ from ray casting, all within %.2f texels "
                "(%.3f m) of an exact shadow edge\n",
                t.name, t.n, differ, g * g, double(worst_texels), double(worst_m));
    EXPECT_LT(differ, g * g / 50) << t.name;
    EXPECT_LE(worst_texels, 3.0f) << t.name;
  }
}

TEST(OmniAgreement, PyramidSceneHasNoSeamPixels) {
  const scenes::Scene scene = scenes::builtin_scene("pyramid");
  const scenes::TriangleSoup soup = scenes::flatten(scene, scenes::InstanceFilter::casters);
  techtest::Soup all;
  all.positions = soup.positions;
  all.indices = soup.indices;
  const scenes::Light& sl = scene.lights.at(0);
  tech::OmniLight light;
  light.position = sl.position;
  light.direction = glm::normalize(sl.direction);
  light.range = sl.range;
  light.hemispherical = true;
  tech::OmniSettings s;
  s.filter = tech::FilterKind::hard;
  s.bias.mode = tech::BiasMode::slope;
  s.map_size = 1024;
  raster::Renderer r(2);
  BuiltOmni pyr = build_omni(r, tech::OmniKind::pyramid, all, light, s);
  s.map_size = 512;  // equal memory would be 418; 512 keeps the cube at least as fine as the pyramid everywhere
  BuiltOmni cube = build_omni(r, tech::OmniKind::cube, all, light, s);
  const int n = 1024;
  // Floor points (y = 0) whose pyramid texel lies within 3 texels of a diagonal of the map.
  int near_seam = 0, differ = 0, seam = 0;
  const float step = 0.005f;
  for (float z = -4.9f; z <= 4.9f; z += step)
    for (float x = -4.9f; x <= 4.9f; x += step) {
      const glm::vec3 p{x, 0.0f, z};
      const glm::vec3 P = pyr.reader.frame.to_light(p);
      const glm::vec2 d = (tech::pyramid_st(P) - 0.5f) * float(n);
      if (std::fabs(std::fabs(d.x) - std::fabs(d.y)) > 3.0f * std::sqrt(2.0f)) continue;
      ++near_seam;
      const glm::vec3 up(0.0f, 1.0f, 0.0f);
      const float vp = hard_visibility(pyr.reader, p, up), vc = hard_visibility(cube.reader, p, up);
      if (vp == vc) continue;
      ++differ;
      // Not a seam if the cube itself changes within 3 pyramid texels of the point (a shadow edge, which the
      // two maps sample differently): the texel's footprint on the floor from a finite difference.
      const float h = 1e-3f;
      const glm::vec2 st = tech::pyramid_st(P) * float(n);
      const float per_m = std::min(
          glm::length(tech::pyramid_st(pyr.reader.frame.to_light(p + glm::vec3(h, 0, 0))) * float(n) - st),
          glm::length(tech::pyramid_st(pyr.reader.frame.to_light(p + glm::vec3(0, 0, h))) * float(n) - st)) / h;
      const float radius = 3.0f / per_m;
      bool edge = false;
      for (int k = 0; k < 16 && !edge; ++k) {
        const float a = float(k) * 0.392699f;
        for (float f : {0.5f, 1.0f})
          edge = edge ||
                 hard_visibility(cube.reader, p + glm::vec3(std::cos(a), 0.0f, std::sin(a)) * radius * f, up) != vc;
      }
      seam += !edge;
    }
  std::printf("pyramid seams: %d floor samples within 3 texels of a region boundary, %d differ from the cube "
              "lookup, %d of them away from any shadow edge\n",
              near_seam, differ, seam);
  EXPECT_GT(near_seam, 10000);
  EXPECT_EQ(seam, 0);
}

}  // namespace
