// Per-caster projective maps (shading/techniques/projective_*): the border ring is white at every map size and
// at every mip level a blurred lookup may read; the frustum is fitted tightly; receivers' boxes are tested
// against it; the q <= 0 and light-side cases get no shadow; decimation cuts triangles but not the silhouette;
// the cache rebuilds exactly the maps whose key changed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "shading/techniques/caster_decimate.h"
#include "shading/techniques/projective_cache.h"
#include "shading/techniques/projective_lookup.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

// A closed box [lo, hi] as one caster part (12 triangles, counter-clockwise outside).
CasterPart box_part(glm::vec3 lo, glm::vec3 hi, float shade = 0.0f) {
  CasterPart p;
  for (int i = 0; i < 8; ++i) p.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  p.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  p.shade = shade;
  return p;
}

Box bounds_of(const CasterPart& p) {
  Box b;
  for (const glm::vec3& v : p.positions) b.min = glm::min(b.min, v), b.max = glm::max(b.max, v);
  return b;
}

bool white(const raster::ColorTarget& t, int x, int y) {
  const uint8_t* p = t.row8(y) + 4 * x;
  return p[0] == 255 && p[1] == 255 && p[2] == 255 && p[3] == 255;
}

const ProjectiveLight kSun{true, {0, 0, 0}, glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f))};
const ProjectiveLight kSpot{false, {0.5f, 6.0f, 0.3f}, {0, -1, 0}};

shading::Quad<glm::vec3> same(glm::vec3 p) { return {p, p, p, p}; }

TEST(ProjectiveMap, BorderTexelsAreWhiteAtEveryMapSize) {
  raster::Renderer r(testsupport::test_threads());
  const CasterPart box = box_part({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f});
  for (const ProjectiveLight& light : {kSun, kSpot}) {
    for (int size = 1; size <= 512; ++size) {
      ProjectiveSettings s;
      s.map_size = size;
      const CasterMap m = build_caster_map(r, light, s, bounds_of(box), std::span(&box, 1));
      ASSERT_TRUE(m.frustum.valid);
      ASSERT_EQ(m.mips.ring, 1);
      const raster::ColorTarget& t = *m.target;
      for (int i = 0; i < size; ++i) {
        ASSERT_TRUE(white(t, i, 0) && white(t, i, size - 1) && white(t, 0, i) && white(t, size - 1, i))
            << "size " << size << " texel " << i;
      }
      if (size >= 3) {  // the caster is drawn: the centre texel is black
        const uint8_t* c = t.row8(size / 2) + 4 * (size / 2);
        EXPECT_EQ(c[0], 0) << "size " << size;
      }
    }
  }
}

TEST(ProjectiveMap, BlurredLookupsReadWhiteEdgesAtEveryLevel) {
  raster::Renderer r(testsupport::test_threads());
  const CasterPart box = box_part({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f});
  for (int size : {5, 17, 33, 63, 64, 65, 127, 128, 129, 255, 256}) {
    for (float bias : {0.5f, 1.0f, 2.0f, 3.0f}) {
      ProjectiveSettings s;
      s.map_size = size;
      s.lod_bias = bias;
      const CasterMap m = build_caster_map(r, kSun, s, bounds_of(box), std::span(&box, 1));
      ASSERT_GE(size - 2 * m.mips.ring, 1);
      // Small maps give up levels whose white edge would leave no inner texel; larger ones get them all.
      if (size >= 64) {
        EXPECT_EQ(m.mips.max_level, int(std::ceil(bias))) << size;
      }
      if (m.mips.max_level > 0) {
        ASSERT_EQ(m.texture.levels(), shading::mip_level_count(size, size));
      }
      for (int level = 0; level <= m.mips.max_level; ++level) {
        const int w = m.texture.width(level);
        for (int i = 0; i < w; ++i)
          for (const glm::ivec2 ij : {glm::ivec2(i, 0), glm::ivec2(i, w - 1), glm::ivec2(0, i), glm::ivec2(w - 1, i)})
            ASSERT_EQ(m.texture.texel(ij.x, ij.y, level), glm::vec4(1.0f))
                << "size " << size << " bias " << bias << " level " << level << " texel " << ij.x << "," << ij.y;
      }
      // Far outside the map, the clamped lookup reads white at any LOD.
      const ProjectiveReader rd = make_projective_reader(m, s);
      EXPECT_EQ(projective_factors(rd, same({40.0f, -3.0f, 40.0f}))[0], 1.0f);
    }
  }
}

TEST(ProjectiveMap, FrustumFitsTheCasterTightly) {
  const Box box{{-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f}};
  for (const ProjectiveLight& light : {kSun, kSpot}) {
    const int size = 128;
    const CasterFrustum f = fit_caster_frustum(light, box, size, 1);
    ASSERT_TRUE(f.valid);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 p{(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                        (i & 4) ? box.max.z : box.min.z};
      const glm::vec4 c = f.texgen * glm::vec4(p, 1.0f);
      const glm::vec2 st = glm::vec2(c.x, c.y) / c.w * float(size);
      lo = glm::min(lo, st), hi = glm::max(hi, st);
    }
    // The caster's corners reach exactly the inner ring on every side: no wasted texels.
    EXPECT_NEAR(lo.x, 1.0f, 1e-3f);
    EXPECT_NEAR(lo.y, 1.0f, 1e-3f);
    EXPECT_NEAR(hi.x, float(size - 1), 1e-3f);
    EXPECT_NEAR(hi.y, float(size - 1), 1e-3f);
  }
}

TEST(ProjectiveMap, ReceiverBoxesAgainstTheFrustum) {
  const Box caster{{-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f}};
  const CasterFrustum down = fit_caster_frustum({true, {}, {0, -1, 0}}, caster, 64, 1);
  EXPECT_TRUE(box_overlaps(down, Box{{-5, -0.1f, -5}, {5, 0, 5}}));       // the ground below
  EXPECT_TRUE(box_overlaps(down, Box{{0.4f, -3, 0.4f}, {0.6f, -2, 0.6f}})); // straddles an edge
  EXPECT_FALSE(box_overlaps(down, Box{{2, -1, -1}, {3, 0, 1}}));            // beside the frustum
  EXPECT_FALSE(box_overlaps(down, Box{{-1, 2.5f, -1}, {1, 3, 1}}));         // above: on the light's side
  const CasterFrustum spot = fit_caster_frustum(kSpot, caster, 64, 1);
  EXPECT_TRUE(box_overlaps(spot, Box{{-1, -0.1f, -1}, {1, 0, 1}}));
  EXPECT_FALSE(box_overlaps(spot, Box{{4, -0.1f, 4}, {5, 0, 5}}));
  EXPECT_FALSE(box_overlaps(spot, Box{{-1, 7, -1}, {1, 8, 1}}));            // behind the light
  // A light inside the caster's box gives no frustum and overlaps nothing.
  const CasterFrustum inside = fit_caster_frustum({false, {0, 1.5f, 0}, {0, -1, 0}}, caster, 64, 1);
  EXPECT_FALSE(inside.valid);
  EXPECT_FALSE(box_overlaps(inside, Box{{-5, -1, -5}, {5, 0, 5}}));
}

// Points behind the projector (q <= 0) and points between the light and the caster read no shadow, although
// textureProj alone would land them inside the black part of the map (back projection).
TEST(ProjectiveMap, QNotPositiveAndLightSideCastNoShadow) {
  raster::Renderer r(0);
  const CasterPart box = box_part({0.0f, 2.5f, -0.2f}, {1.0f, 3.5f, 0.8f});
  ProjectiveSettings s;
  s.map_size = 64;
  const CasterMap m = build_caster_map(r, kSpot, s, bounds_of(box), std::span(&box, 1));
  ASSERT_TRUE(m.frustum.perspective);
  const ProjectiveReader rd = make_projective_reader(m, s);
  const glm::vec3 below(0.5f, 0.0f, 0.3f);  // on the spot's axis, behind the caster: shadowed
  EXPECT_EQ(projective_factors(rd, same(below))[0], 0.0f);
  // Mirror image through the light: q < 0, and what textureProj alone reads there.
  const glm::vec3 mirror = 2.0f * kSpot.position - below;
  const glm::vec4 c = rd.texgen * glm::vec4(mirror, 1.0f);
  ASSERT_LT(c.w, 0.0f);
  EXPECT_EQ(shading::texture_proj(rd.texture, rd.sampler, glm::vec3(c.x, c.y, c.w)).r, 0.0f);
  EXPECT_EQ(projective_factors(rd, same(mirror))[0], 1.0f);
  // q = 0: level with the light.
  EXPECT_EQ(projective_factors(rd, same(kSpot.position + glm::vec3(1.0f, 0.0f, 0.0f)))[0], 1.0f);
  // Between the light and the caster (q > 0, inside the map): nearer the light than the caster.
  EXPECT_EQ(projective_factors(rd, same({0.5f, 4.5f, 0.3f}))[0], 1.0f);
}

TEST(ProjectiveMap, FadeAndShadeAndGreyCasters) {
  raster::Renderer r(0);
  const CasterPart opaque = box_part({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f}, caster_shade_for(0.25f, 1.0f));
  const CasterPart glass = box_part({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f}, caster_shade_for(0.0f, 0.4f));
  ProjectiveSettings s;
  s.map_size = 32;
  s.fade_start = 2.0f;
  s.fade_end = 4.0f;
  const ProjectiveLight down{true, {}, {0, -1, 0}};
  const CasterMap m = build_caster_map(r, down, s, bounds_of(opaque), std::span(&opaque, 1));
  const ProjectiveReader rd = make_projective_reader(m, s);
  const float texel = 1.0f / 255.0f;
  EXPECT_NEAR(projective_factors(rd, same({0, 1.0f, 0}))[0], 0.25f, texel);   // 1 m behind the near side
  EXPECT_NEAR(projective_factors(rd, same({0, -1.0f, 0}))[0], 0.625f, texel); // 3 m: half faded
  EXPECT_FLOAT_EQ(projective_factors(rd, same({0, -4.0f, 0}))[0], 1.0f);           // beyond fade_end
  const CasterMap g = build_caster_map(r, down, s, bounds_of(glass), std::span(&glass, 1));
  EXPECT_NEAR(projective_factors(make_projective_reader(g, s), same({0, 1.0f, 0}))[0], 0.6f, texel);
}

TEST(ProjectiveMap, DecimationMatchesTheMapResolution) {
  // A finely tessellated sphere (radius 1, 512 × 256 quads) into a 32² map.
  CasterPart sphere;
  const int seg = 512, rings = 256;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i <= seg; ++i) {
      const float th = 3.14159265f * float(j) / rings, ph = 6.2831853f * float(i) / seg;
      sphere.positions.push_back({std::sin(th) * std::cos(ph), 3.0f + std::cos(th), std::sin(th) * std::sin(ph)});
    }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < seg; ++i) {
      const uint32_t a = uint32_t(j * (seg + 1) + i), b = a + 1, c = a + uint32_t(seg + 1), d = c + 1;
      sphere.indices.insert(sphere.indices.end(), {a, c, b, b, c, d});
    }
  raster::Renderer r(testsupport::test_threads());
  ProjectiveSettings s;
  s.map_size = 32;
  s.decimate = false;
  const CasterMap full = build_caster_map(r, kSun, s, bounds_of(sphere), std::span(&sphere, 1));
  s.decimate = true;
  const CasterMap low = build_caster_map(r, kSun, s, bounds_of(sphere), std::span(&sphere, 1));
  EXPECT_EQ(full.triangles, uint64_t(seg * rings * 2));
  EXPECT_LT(low.triangles * 5, full.triangles) << low.triangles;
  // Only silhouette texels may differ, and only a few of them.
  int differ = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) differ += full.target->row8(y)[4 * x] != low.target->row8(y)[4 * x];
  EXPECT_LE(differ, 8);
  std::printf("decimation into a 32² map: %llu -> %llu triangles, %d texels differ\n",
              static_cast<unsigned long long>(full.triangles), static_cast<unsigned long long>(low.triangles), differ);
}

TEST(ProjectiveCache, RebuildsOnlyWhatChanged) {
  raster::Renderer r(0);
  ProjectiveCache cache;
  ProjectiveSettings s;
  s.map_size = 16;
  const CasterPart a = box_part({0, 1, 0}, {1, 2, 1}), b = box_part({3, 1, 0}, {4, 2, 1});
  const uint64_t ha = mesh_content_hash(a.positions, a.indices), hb = mesh_content_hash(b.positions, b.indices);
  int builds = 0;
  auto frame = [&](const ProjectiveLight& light, glm::mat4 ta, uint64_t mesh_a) {
    cache.begin_frame();
    const CasterInstanceKey ka{ta, 0.0f, mesh_a}, kb{glm::mat4(1.0f), 0.0f, hb};
    cache.get(0, make_caster_key(light, s, std::span(&ka, 1)), [&] {
      ++builds;
      return build_caster_map(r, light, s, bounds_of(a), std::span(&a, 1));
    });
    cache.get(1, make_caster_key(light, s, std::span(&kb, 1)), [&] {
      ++builds;
      return build_caster_map(r, light, s, bounds_of(b), std::span(&b, 1));
    });
    cache.end_frame();
  };
  frame(kSun, glm::mat4(1.0f), ha);
  EXPECT_EQ(cache.rebuilt(), 2u);
  frame(kSun, glm::mat4(1.0f), ha);
  EXPECT_EQ(cache.rebuilt(), 0u);
  EXPECT_EQ(cache.reused(), 2u);
  glm::mat4 moved(1.0f);
  moved[3].x = 0.25f;
  frame(kSun, moved, ha);  // caster a moved
  EXPECT_EQ(cache.rebuilt(), 1u);
  frame(kSun, moved, ha ^ 1);  // caster a's mesh changed
  EXPECT_EQ(cache.rebuilt(), 1u);
  ProjectiveLight turned = kSun;
  turned.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f));
  frame(turned, moved, ha ^ 1);  // the light changed: both
  EXPECT_EQ(cache.rebuilt(), 2u);
  EXPECT_EQ(builds, 6);
  cache.begin_frame();
  cache.end_frame();
  EXPECT_EQ(cache.size(), 0u);  // casters gone from the scene leave the cache
}

TEST(ProjectiveMap, DefaultsRow) {
  const TechniqueInfo& d = info(Technique::projective);
  EXPECT_EQ(d.encoding, "caster-mask");
  EXPECT_EQ(int(d.map_size), ProjectiveSettings{}.map_size);
}

}  // namespace
