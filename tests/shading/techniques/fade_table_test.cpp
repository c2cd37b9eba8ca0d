// Fade tables of projective shadows (shading/techniques/fade_table.*, read by projective_lookup.h): parsing and
// refusals, the LINEAR lookup with the default two-texel table giving exactly the formula's ramp (every factor
// bit for bit), and a non-default table setting the shadow's strength at a known distance to its value.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <span>
#include <string>

#include "shading/techniques/fade_table.h"
#include "shading/techniques/projective_lookup.h"
#include "shading/techniques/projective_map.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

TEST(FadeTable, ParsesPresetsAndLists) {
  std::string why;
  EXPECT_EQ(*parse_fade_table("linear", why), (std::vector<float>{1.0f, 0.0f}));
  const std::vector<float> smooth = *parse_fade_table("smoothstep", why);
  ASSERT_EQ(smooth.size(), size_t(kSmoothstepTexels));
  EXPECT_EQ(smooth.front(), 1.0f);
  EXPECT_EQ(smooth.back(), 0.0f);
  EXPECT_NEAR(smooth[51], 1.0 - (0.2 * 0.2 * (3 - 0.4)), 1e-6);  // t = 51 / 255 = 0.2
  EXPECT_EQ(*parse_fade_table(" 1, 0.5 ,0 ", why), (std::vector<float>{1.0f, 0.5f, 0.0f}));
  for (const char* bad : {"1", "", "a,b", "1,2", "1,,0", "1,-0.1", "0.5,nan", "steep"}) {
    EXPECT_FALSE(parse_fade_table(bad, why)) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
  std::string many = "1";
  for (int i = 1; i < kMaxFadeTexels; ++i) many += ",0.5";
  EXPECT_TRUE(parse_fade_table(many, why));
  EXPECT_FALSE(parse_fade_table(many + ",0", why));
  EXPECT_NE(why.find("257"), std::string::npos) << why;
}

TEST(FadeTable, LinearTableIsTheRampBitForBit) {
  const std::vector<float> linear{1.0f, 0.0f};
  const shading::Texture2D lut = make_fade_texture(linear);
  ASSERT_EQ(lut.width(), 2);
  EXPECT_EQ(lut.texel(0, 0).r, 0.0f);  // the texels hold 1 − strength
  EXPECT_EQ(lut.texel(1, 0).r, 1.0f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 100000; ++i) {
    const float t = i < 4 ? float(i) / 3.0f : u(rng) * (i % 2 ? 1.0f : 1e-3f);
    ASSERT_EQ(bits(fade_at(lut, t)), bits(t)) << t;
  }
  EXPECT_EQ(fade_at(lut, -1.0f), 0.0f);  // clamped to the ends
  EXPECT_EQ(fade_at(lut, 7.0f), 1.0f);
}

// The caster of projective_map_test's fade test: a box from y = 1 to 2 under a light straight down, drawn black
// into a 32² map; the fade runs from 2 to 4 m behind its near side (y = 2), so y = 0 is t = 0, y = −1 is t = 0.5.
struct Caster {
  raster::Renderer renderer{0};
  ProjectiveSettings s;
  CasterMap map;
  Caster() {
    CasterPart p;
    const glm::vec3 lo{-0.5f, 1.0f, -0.5f}, hi{0.5f, 2.0f, 0.5f};
    for (int i = 0; i < 8; ++i) p.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    p.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    s.map_size = 32;
    s.fade_start = 2.0f;
    s.fade_end = 4.0f;
    map = build_caster_map(renderer, ProjectiveLight{true, {}, {0, -1, 0}}, s, Box{lo, hi}, std::span(&p, 1));
  }
};

shading::Quad<glm::vec3> same(glm::vec3 p) { return {p, p, p, p}; }

TEST(FadeTable, DefaultTableReaderEqualsTheFormulaReader) {
  Caster c;
  for (const float shade : {0.0f, 0.3f}) {
    c.s.caster_shade = shade;  // (the reader does not look at it; the map is the same)
    const ProjectiveReader formula = make_projective_reader(c.map, c.s);
    ProjectiveSettings t = c.s;
    t.fade_lookup = FadeLookup::texture;  // fade_table left at its default: linear
    const ProjectiveReader texture = make_projective_reader(c.map, t);
    ASSERT_FALSE(texture.fade_table.empty());
    ASSERT_TRUE(formula.fade_table.empty());
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> xz(-0.7f, 0.7f), y(-6.0f, 2.5f);
    int faded = 0;
    for (int i = 0; i < 20000; ++i) {
      const shading::Quad<glm::vec3> p = {glm::vec3(xz(rng), y(rng), xz(rng)), glm::vec3(xz(rng), y(rng), xz(rng)),
                                          glm::vec3(xz(rng), y(rng), xz(rng)), glm::vec3(xz(rng), y(rng), xz(rng))};
      const shading::Quad<float> a = projective_factors(formula, p), b = projective_factors(texture, p);
      for (size_t l = 0; l < 4; ++l) {
        ASSERT_EQ(bits(a[l]), bits(b[l])) << p[l].x << " " << p[l].y << " " << p[l].z;
        faded += a[l] > 0.0f && a[l] < 1.0f;
      }
    }
    EXPECT_GT(faded, 1000);  // the ramp was crossed, not only its ends
  }
}

TEST(FadeTable, TableValueIsTheShadowStrengthAtItsDistance) {
  Caster c;
  c.s.fade_lookup = FadeLookup::texture;
  c.s.fade_table = {1.0f, 0.2f, 0.6f};  // full at 2 m, 20 % at 3 m, 60 % from 4 m on
  const ProjectiveReader rd = make_projective_reader(c.map, c.s);
  // The map is black under the box: the factor is 1 − strength.
  EXPECT_EQ(projective_factors(rd, same({0, 1.0f, 0}))[0], 0.0f);                // 1 m: before the fade
  EXPECT_NEAR(projective_factors(rd, same({0, -1.0f, 0}))[0], 0.8f, 1e-5f);     // 3 m, t = 0.5: texel 1
  EXPECT_NEAR(projective_factors(rd, same({0, -0.5f, 0}))[0], 0.4f, 1e-5f);     // 2.5 m: between 1 and 0.2
  EXPECT_NEAR(projective_factors(rd, same({0, -1.5f, 0}))[0], 0.6f, 1e-5f);     // 3.5 m: between 0.2 and 0.6
  EXPECT_NEAR(projective_factors(rd, same({0, -10.0f, 0}))[0], 0.4f, 1e-5f);    // past fade_end: the last texel
  EXPECT_EQ(projective_factors(rd, same({40.0f, -1.0f, 40.0f}))[0], 1.0f);      // outside the map: no shadow
  // The formula at 3 m: half faded.
  c.s.fade_lookup = FadeLookup::formula;
  EXPECT_NEAR(projective_factors(make_projective_reader(c.map, c.s), same({0, -1.0f, 0}))[0], 0.5f, 1e-5f);
}

}  // namespace
