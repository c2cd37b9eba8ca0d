// The omnidirectional maps' addressing and storage: a billboard placed in a direction known to lie in a given
// cube face, paraboloid hemisphere or pyramid region lands on the texel GL's face table, the paraboloid
// formula or the pyramid's closed form predicts (written out independently here), with distance / range
// stored there; the RGBA8 pack/unpack round trip; points behind a hemispherical light are unlit; the pyramid
// map of a closed room has no texel left unwritten (no seams between its four passes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/shading/techniques/omni_test_util.h"

namespace {

using namespace omnitest;

tech::OmniSettings settings(int size) {
  tech::OmniSettings s;
  s.map_size = size;
  s.depth_format = raster::DepthFormat::d32f;
  s.filter = tech::FilterKind::hard;
  s.bias.mode = tech::BiasMode::constant;
  s.bias.constant = 0.002f;
  return s;
}

struct Texel {
  int x, y;  // in the target
};

// Builds a map with one billboard at light + dir · dist and checks the predicted texel holds dist / range,
// and that the reader sees a point behind the billboard as shadowed and one in front as lit.
void check_direction(tech::OmniKind kind, const tech::OmniLight& light, glm::vec3 dir, Texel expect, int size) {
  raster::Renderer r(0);
  techtest::Soup soup;
  const float dist = 4.0f;
  const glm::vec3 d = glm::normalize(dir);
  billboard(soup, light.position, light.position + d * dist, 0.08f);
  const tech::OmniSettings s = settings(size);
  BuiltOmni b = build_omni(r, kind, soup, light, s);
  const raster::DepthTarget& t = *b.set->targets[0];
  const float stored = t.value(expect.x, expect.y);
  EXPECT_NEAR(stored, dist / light.range, 2e-4f) << "dir " << dir.x << "," << dir.y << "," << dir.z << " texel "
                                                 << expect.x << "," << expect.y;
  EXPECT_EQ(hard_visibility(b.reader, light.position + d * (dist + 1.0f)), 0.0f);
  EXPECT_EQ(hard_visibility(b.reader, light.position + d * (dist - 1.0f)), 1.0f);
}

TEST(OmniMap, CubeDirectionsLandOnGlFaceTexels) {
  tech::OmniLight light;
  light.position = {0.5f, 1.0f, -0.25f};
  light.range = 20.0f;
  const int n = 128;
  // GL table 8.19 written out: face, sc, tc, ma.
  struct Case {
    glm::vec3 d;
    int face;
  };
  const Case cases[] = {{{1.0f, 0.3f, -0.2f}, 0}, {{-1.0f, -0.4f, 0.1f}, 1}, {{0.2f, 1.0f, 0.35f}, 2},
                        {{-0.3f, -1.0f, 0.2f}, 3}, {{0.25f, -0.3f, 1.0f}, 4}, {{-0.1f, 0.45f, -1.0f}, 5}};
  for (const Case& c : cases) {
    const glm::vec3 r = c.d;
    float sc = 0, tc = 0, ma = 0;
    switch (c.face) {
      case 0: sc = -r.z, tc = -r.y, ma = r.x; break;
      case 1: sc = r.z, tc = -r.y, ma = -r.x; break;
      case 2: sc = r.x, tc = r.z, ma = r.y; break;
      case 3: sc = r.x, tc = -r.z, ma = -r.y; break;
      case 4: sc = r.x, tc = -r.y, ma = r.z; break;
      case 5: sc = -r.x, tc = -r.y, ma = -r.z; break;
    }
    const float s = (sc / ma + 1.0f) / 2.0f, t = (tc / ma + 1.0f) / 2.0f;
    EXPECT_EQ(shading::cube_face_of(r), c.face);
    const Texel e{n * (c.face % 3) + int(s * float(n)), n * (c.face / 3) + int(t * float(n))};
    check_direction(tech::OmniKind::cube, light, r, e, n);
  }
}

TEST(OmniMap, ParaboloidDirectionsLandInTheirHemisphere) {
  tech::OmniLight light;
  light.position = {0.0f, 2.0f, 0.0f};
  light.direction = {0.0f, 0.0f, 1.0f};  // split plane z = 0 of the light frame
  light.range = 20.0f;
  const int n = 128;
  const tech::LightFrame f = tech::light_frame(light.position, light.direction);
  for (const glm::vec3 local : {glm::vec3(0.3f, -0.2f, 0.8f), glm::vec3(-0.6f, 0.5f, 0.3f), glm::vec3(0.4f, 0.3f, -0.7f),
                                glm::vec3(-0.2f, -0.5f, -0.4f)}) {
    const glm::vec3 p = glm::normalize(local);
    const bool front = p.z >= 0.0f;
    const float den = front ? 1.0f + p.z : 1.0f - p.z;
    const float s = 0.5f * p.x / den + 0.5f, t = 0.5f * p.y / den + 0.5f;
    const Texel e{(front ? 0 : n) + int(s * float(n)), int(t * float(n))};
    check_direction(tech::OmniKind::paraboloid, light, f.to_world_dir(p), e, n);
  }
}

TEST(OmniMap, PyramidDirectionsLandInTheirRegion) {
  tech::OmniLight light;
  light.position = {0.0f, 3.0f, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.range = 12.0f;
  light.hemispherical = true;
  const int n = 256;
  const tech::LightFrame f = tech::light_frame(light.position, light.direction);
  struct Case {
    glm::vec3 local;
    int region;  // 0 top, 1 right, 2 bottom, 3 left
  };
  const Case cases[] = {{{0.2f, 0.7f, 0.6f}, 0}, {{0.9f, -0.3f, 0.4f}, 1}, {{-0.1f, -0.8f, 0.3f}, 2},
                        {{-0.7f, 0.2f, 0.5f}, 3}, {{0.05f, 0.02f, 1.0f}, 1}};
  for (const Case& c : cases) {
    const glm::vec3 p = glm::normalize(c.local);
    EXPECT_EQ(tech::pyramid_region(p.x, p.y), c.region);
    // Closed form: (s, t) = 0.5 + (x, y) / (2 (max(|x|, |y|) + z)).
    const float m = std::max(std::fabs(p.x), std::fabs(p.y));
    const float s = 0.5f + p.x / (2.0f * (m + p.z)), t = 0.5f + p.y / (2.0f * (m + p.z));
    const glm::vec2 st = tech::pyramid_st(p);
    EXPECT_NEAR(st.x, s, 1e-6f);
    EXPECT_NEAR(st.y, t, 1e-6f);
    const Texel e{int(s * float(n)), int(t * float(n))};
    // The texel lies in the region's half of the map.
    const int h = n / 2;
    switch (c.region) {
      case 0: EXPECT_GE(e.y, h); break;
      case 1: EXPECT_GE(e.x, h); break;
      case 2: EXPECT_LT(e.y, h); break;
      case 3: EXPECT_LT(e.x, h); break;
      default: ADD_FAILURE() << "region " << c.region;
    }
    check_direction(tech::OmniKind::pyramid, light, f.to_world_dir(p), e, n);
  }
}

// The four pass cameras match the description: tilts of 45° about x or y, fovY 90° and fovX 2·atan(√2) for
// passes 1 and 3, swapped for 2 and 4, and the viewports top, right, bottom, left.
TEST(OmniMap, PyramidPassesFollowTheDescription) {
  const int n = 512;
  const float wide = 2.0f * std::atan(std::sqrt(2.0f));
  for (int k = 0; k < 4; ++k) {
    const tech::PyramidPassCamera c = tech::pyramid_pass_camera(k, n);
    EXPECT_NEAR(glm::dot(c.forward, glm::vec3(0, 0, 1)), std::sqrt(0.5f), 1e-6f);  // tilted 45° off the axis
    const float fov_x = 2.0f * std::atan(c.aspect * std::tan(c.fov_y / 2.0f));
    if (k % 2 == 0) {
      EXPECT_NEAR(c.fov_y, glm::radians(90.0f), 1e-6f);
      EXPECT_NEAR(fov_x, wide, 1e-5f);
      EXPECT_NEAR(wide, glm::radians(109.47122f), 1e-6f);
    } else {
      EXPECT_NEAR(c.fov_y, wide, 1e-6f);
      EXPECT_NEAR(fov_x, glm::radians(90.0f), 1e-5f);
    }
  }
  EXPECT_EQ(tech::pyramid_pass_camera(0, n).viewport, (raster::Rect{0, 256, 512, 256}));
  EXPECT_EQ(tech::pyramid_pass_camera(1, n).viewport, (raster::Rect{256, 0, 256, 512}));
  EXPECT_EQ(tech::pyramid_pass_camera(2, n).viewport, (raster::Rect{0, 0, 512, 256}));
  EXPECT_EQ(tech::pyramid_pass_camera(3, n).viewport, (raster::Rect{0, 0, 256, 512}));
}

// A closed box around the light: every texel of the pyramid map sees a wall, so none may keep the clear
// value 1 — a texel that no pass claims (a seam between two triangles) would.
TEST(OmniMap, PyramidMapOfAClosedRoomHasNoUnwrittenTexel) {
  techtest::Soup room;
  const float a = 3.0f;
  // Six faces of a cube [−a, a]³ (winding irrelevant: no culling).
  room.quad({-a, -a, -a}, {a, -a, -a}, {a, -a, a}, {-a, -a, a});
  room.quad({-a, a, -a}, {a, a, -a}, {a, a, a}, {-a, a, a});
  room.quad({-a, -a, -a}, {-a, a, -a}, {-a, a, a}, {-a, -a, a});
  room.quad({a, -a, -a}, {a, a, -a}, {a, a, a}, {a, -a, a});
  room.quad({-a, -a, -a}, {a, -a, -a}, {a, a, -a}, {-a, a, -a});
  room.quad({-a, -a, a}, {a, -a, a}, {a, a, a}, {-a, a, a});
  for (const glm::vec3 dir : {glm::vec3(0, -1, 0), glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f))}) {
    tech::OmniLight light;
    light.position = {0.1f, 0.4f, -0.2f};
    light.direction = dir;
    light.range = 12.0f;
    light.hemispherical = true;
    raster::Renderer r(2);
    for (int n : {256, 250}) {
      BuiltOmni b = build_omni(r, tech::OmniKind::pyramid, room, light, settings(n));
      const raster::DepthTarget& t = *b.set->targets[0];
      int unwritten = 0;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) unwritten += t.value(x, y) >= 1.0f;
      EXPECT_EQ(unwritten, 0) << "size " << n;
    }
  }
}

// The description's base-256 pack and unpack: exact to float precision before storage, and within the error
// that storing each channel as round(c · 255) / 255 leaves (the scheme's known flaw: the digits are base 256
// but the channels hold 255 steps): at most 128/65280 from the top digit plus the lower ones' share, 0.00197
// (about 1/508) of the range, measured.
TEST(OmniMap, Rgba8PackRoundTrip) {
  float worst_float = 0.0f, worst_rgba8 = 0.0f;
  for (int k = 0; k < 200000; ++k) {
    const float v = float(k) / 200000.0f;
    const glm::vec4 c = tech::pack_depth_rgba8(v);
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(c[i], 0.0f);
      EXPECT_LT(c[i], 1.0f);
    }
    worst_float = std::max(worst_float, std::fabs(tech::unpack_depth_rgba8(c) - v));
    glm::vec4 q;
    for (int i = 0; i < 4; ++i) q[i] = std::nearbyint(c[i] * 255.0f) / 255.0f;
    worst_rgba8 = std::max(worst_rgba8, std::fabs(tech::unpack_depth_rgba8(q) - v));
  }
  std::printf("rgba8 pack: float round trip %.3g, through 8-bit channels %.3g\n", double(worst_float),
              double(worst_rgba8));
  EXPECT_LT(worst_float, 2e-7f);
  EXPECT_LT(worst_rgba8, 0.00197f);

  // A packed paraboloid map reads back what the float map holds, within that bound.
  tech::OmniLight light;
  light.position = {0.0f, 2.0f, 0.0f};
  light.range = 10.0f;
  techtest::Soup soup;
  billboard(soup, light.position, {1.0f, 0.5f, 0.5f}, 0.6f);
  billboard(soup, light.position, {-0.5f, 4.0f, 0.5f}, 0.8f);
  raster::Renderer r(0);
  tech::OmniSettings s = settings(128);
  BuiltOmni f = build_omni(r, tech::OmniKind::paraboloid, soup, light, s);
  s.packing = tech::DepthPacking::rgba8;
  BuiltOmni p = build_omni(r, tech::OmniKind::paraboloid, soup, light, s);
  int written = 0;
  for (size_t pass = 0; pass < 2; ++pass) {
    const shading::Texture2D a = tech::paraboloid_depth_texture(*f.set, pass, settings(128));
    const shading::Texture2D b = tech::paraboloid_depth_texture(*p.set, pass, s);
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 128; ++x) {
        const float da = a.texel(x, y).r, db = b.texel(x, y).r;
        if (da >= 1.0f) {
          EXPECT_GE(db, 1.0f);
          continue;
        }
        ++written;
        EXPECT_NEAR(da, db, 0.00197f);
      }
  }
  EXPECT_GT(written, 100);
}

// Behind a hemispherical light nothing is lit, whatever the technique; a point light's paraboloid reads the
// back map there instead.
TEST(OmniMap, BehindTheHemisphereIsUnlit) {
  techtest::Soup empty;
  empty.quad({50, 50, 50}, {51, 50, 50}, {51, 51, 50}, {50, 51, 50});  // far away, out of range
  tech::OmniLight light;
  light.position = {0.0f, 3.0f, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.range = 10.0f;
  light.hemispherical = true;
  raster::Renderer r(0);
  const glm::vec3 below{1.0f, 1.0f, 0.5f}, above{1.0f, 5.0f, 0.5f};
  for (tech::OmniKind k : {tech::OmniKind::cube, tech::OmniKind::paraboloid, tech::OmniKind::pyramid}) {
    BuiltOmni b = build_omni(r, k, empty, light, settings(64));
    EXPECT_EQ(hard_visibility(b.reader, below), 1.0f) << int(k);
    EXPECT_EQ(hard_visibility(b.reader, above), 0.0f) << int(k);
  }
  light.hemispherical = false;
  BuiltOmni p = build_omni(r, tech::OmniKind::paraboloid, empty, light, settings(64));
  EXPECT_EQ(hard_visibility(p.reader, above), 1.0f);
  BuiltOmni c = build_omni(r, tech::OmniKind::cube, empty, light, settings(64));
  EXPECT_EQ(hard_visibility(c.reader, above), 1.0f);
  // The pyramid is a 180° map whatever the light type.
  BuiltOmni y = build_omni(r, tech::OmniKind::pyramid, empty, light, settings(64));
  EXPECT_EQ(hard_visibility(y.reader, above), 0.0f);
}

}  // namespace
