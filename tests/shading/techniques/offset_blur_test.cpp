// The projective maps' offset blur (shading/techniques/offset_blur.*): a hard black/white edge becomes the
// closed-form ramp of bilinear lookups at ±d texels (exact 8-bit values), a single black texel the separable
// tent, white stays exactly white, and the passes give the same bytes at every thread count. Through
// build_caster_map: the border ring of a blurred map (with and without mips) stays white.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "shading/techniques/offset_blur.h"
#include "shading/techniques/projective_lookup.h"
#include "shading/techniques/projective_map.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

using Target = std::unique_ptr<raster::ColorTarget>;

Target make_target(int w, int h) { return std::make_unique<raster::ColorTarget>(w, h, raster::ColorFormat::rgba8); }

// GL's 8-bit store of v: clamp, round to nearest.
int code(double v) { return int(std::nearbyint(std::clamp(v, 0.0, 1.0) * 255.0)); }

void fill(raster::ColorTarget& t, auto&& value) {
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) {
      const float v = value(x, y);
      t.write(x, y, glm::vec4(v, v, v, 1.0f));
    }
}

int red(const raster::ColorTarget& t, int x, int y) { return t.row8(y)[4 * x]; }

TEST(OffsetBlur, HardEdgeGivesTheBilinearRamp) {
  raster::Renderer r(testsupport::test_threads());
  // Black for x < 8, white from x = 8, on a 16 × 8 map. Per axis a pass is (d/2, 1 − d, d/2): the texel left of
  // the edge gets d/2 of white, the one right of it 1 − d/2; the rest are unchanged (the clamped edge included).
  for (const float d : {0.5f, 0.25f, 1.0f}) {
    Target map = make_target(16, 8), scratch = make_target(16, 8);
    fill(*map, [](int x, int) { return x < 8 ? 0.0f : 1.0f; });
    offset_blur(r, map, scratch, 1, d);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x) {
        const int want = x == 7 ? code(d / 2.0) : x == 8 ? code(1.0 - d / 2.0) : (x < 8 ? 0 : 255);
        ASSERT_EQ(red(*map, x, y), want) << "d " << d << " texel " << x << "," << y;
      }
  }
  // Exact values at d = 0.5 and 0.25: 0.25 -> 64, 0.75 -> 191, 0.125 -> 32, 0.875 -> 223.
  EXPECT_EQ(code(0.25), 64);
  EXPECT_EQ(code(0.75), 191);
  EXPECT_EQ(code(0.125), 32);
  EXPECT_EQ(code(0.875), 223);
  // A second pass applies the same kernel to the 8-bit result of the first: the ramp widens by one texel a side.
  Target map = make_target(16, 8), scratch = make_target(16, 8);
  fill(*map, [](int x, int) { return x < 8 ? 0.0f : 1.0f; });
  offset_blur(r, map, scratch, 2, 0.5f);
  const double p1[16] = {0, 0, 0, 0, 0, 0, 0, 64 / 255.0, 191 / 255.0, 1, 1, 1, 1, 1, 1, 1};
  for (int x = 0; x < 16; ++x) {
    const double l = p1[std::max(x - 1, 0)], c = p1[x], rr = p1[std::min(x + 1, 15)];
    EXPECT_EQ(red(*map, x, 3), code(0.5 * c + 0.25 * (l + rr))) << x;
  }
  EXPECT_EQ(red(*map, 6, 3), 16);   // 64 / 4
  EXPECT_EQ(red(*map, 9, 3), 239);  // (191 + 2 · 255 + 255) / 4 = 239
}

TEST(OffsetBlur, OneBlackTexelGivesTheSeparableTent) {
  raster::Renderer r(testsupport::test_threads());
  Target map = make_target(8, 8), scratch = make_target(8, 8);
  fill(*map, [](int x, int y) { return x == 4 && y == 4 ? 0.0f : 1.0f; });
  offset_blur(r, map, scratch, 1, 0.5f);
  // (1/4, 1/2, 1/4) ⊗ (1/4, 1/2, 1/4): the black texel keeps 1/4 of its darkness, its side neighbours 1/8, its
  // diagonal ones 1/16.
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const int dx = std::abs(x - 4), dy = std::abs(y - 4);
      const double w = (dx == 0 ? 0.5 : dx == 1 ? 0.25 : 0.0) * (dy == 0 ? 0.5 : dy == 1 ? 0.25 : 0.0);
      EXPECT_EQ(red(*map, x, y), code(1.0 - w)) << x << "," << y;
    }
  EXPECT_EQ(red(*map, 4, 4), 191);
  EXPECT_EQ(red(*map, 5, 4), 223);
  EXPECT_EQ(red(*map, 5, 5), 239);
}

TEST(OffsetBlur, WhiteStaysExactlyWhite) {
  raster::Renderer r(testsupport::test_threads());
  for (const float d : {0.05f, 0.3f, 0.5f, 0.77f, 1.0f}) {
    Target map = make_target(37, 29), scratch = make_target(37, 29);
    map->clear(glm::vec4(1.0f));
    offset_blur(r, map, scratch, 5, d);
    for (int y = 0; y < 29; ++y)
      for (int x = 0; x < 37; ++x) ASSERT_EQ(red(*map, x, y), 255) << d << " " << x << "," << y;
  }
}

TEST(OffsetBlur, SameBytesAtEveryThreadCount) {
  std::vector<uint8_t> first;
  for (int threads : {0, 1, 2, 4}) {
    raster::Renderer r(threads);
    Target map = make_target(77, 53), scratch = make_target(77, 53);
    fill(*map, [](int x, int y) { return float((x * 7919 + y * 104729) % 251) / 250.0f; });
    offset_blur(r, map, scratch, 3, 0.3f);
    std::vector<uint8_t> bytes;
    for (int y = 0; y < 53; ++y) bytes.insert(bytes.end(), map->row8(y), map->row8(y) + 77 * 4);
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << "threads " << threads;
  }
}

TEST(OffsetBlur, RefusesBadArguments) {
  raster::Renderer r(0);
  raster::ColorTarget a(8, 8, raster::ColorFormat::rgba8), b(8, 4, raster::ColorFormat::rgba8);
  EXPECT_THROW(offset_blur_pass(r, a, a, 0.5f), std::invalid_argument);
  EXPECT_THROW(offset_blur_pass(r, a, b, 0.5f), std::invalid_argument);
  raster::ColorTarget c(8, 8, raster::ColorFormat::rgba8);
  EXPECT_THROW(offset_blur_pass(r, a, c, 0.0f), std::invalid_argument);
  EXPECT_THROW(offset_blur_pass(r, a, c, 1.5f), std::invalid_argument);
}

// A closed box [lo, hi] as one caster part.
CasterPart box_part(glm::vec3 lo, glm::vec3 hi) {
  CasterPart p;
  for (int i = 0; i < 8; ++i) p.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  p.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return p;
}

// The article's requirement that the map's edge is a no-op: the caster is drawn blur_passes texels further in,
// so after the last pass the ring every level reads is still exactly white; small maps give up passes.
TEST(OffsetBlur, BlurredCasterMapsKeepTheirBorderWhite) {
  raster::Renderer r(testsupport::test_threads());
  const CasterPart box = box_part({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f});
  const Box bounds{{-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f}};
  const ProjectiveLight sun{true, {0, 0, 0}, glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f))};
  for (int size : {3, 4, 5, 8, 9, 17, 32, 64, 65, 128}) {
    for (int passes : {1, 2, 4, 16}) {
      for (float bias : {0.0f, 2.0f}) {
        ProjectiveSettings s;
        s.map_size = size;
        s.blur_passes = passes;
        s.blur_offset = 1.0f;  // the widest reach
        s.lod_bias = bias;
        const CasterMap m = build_caster_map(r, sun, s, bounds, std::span(&box, 1));
        ASSERT_GE(size - 2 * (m.mips.ring + m.blur_passes), 1) << size;
        if (size >= 2 * (m.mips.ring + passes) + 1) {
          EXPECT_EQ(m.blur_passes, passes) << size;
        }
        for (int level = 0; level <= m.mips.max_level; ++level) {
          const int w = m.texture.width(level);
          for (int i = 0; i < w; ++i)
            for (const glm::ivec2 ij : {glm::ivec2(i, 0), glm::ivec2(i, w - 1), glm::ivec2(0, i), glm::ivec2(w - 1, i)})
              ASSERT_EQ(m.texture.texel(ij.x, ij.y, level), glm::vec4(1.0f))
                  << "size " << size << " passes " << passes << " bias " << bias << " level " << level;
        }
        // And the blur did something: grey texels between the black and the white.
        if (size >= 17) {
          int grey = 0;
          for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) grey += red(*m.target, x, y) > 0 && red(*m.target, x, y) < 255;
          EXPECT_GT(grey, 0) << size << " " << passes;
        }
      }
    }
  }
}

}  // namespace
