// The tutorial variant of the Poisson filters (shading/techniques/tutorial_random.h, shadow_filters.h): the
// tutorial's GLSL random reproduces values worked out by hand from its formula, and its accumulation gives
// exactly 1 - 0.2·k for k shadowed taps (clamped at 0 past five of sixteen), with the taps its random picks.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "raster/target.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/tutorial_random.h"

namespace {

namespace tech = shading::tech;

// The tutorial's float fold for k shadowed taps: 1.0f, then k times `-= 0.2f * (1.0f - 0.0f)` (lit taps
// subtract 0.2f * 0.0f = 0, which changes nothing, so their order does not matter).
float tutorial_fold(int k) {
  float v = 1.0f;
  for (int i = 0; i < k; ++i) v -= 0.2f * (1.0f - 0.0f);
  return v;
}

// A d32f map of size² texels, all at depth 1 (lit for ref 0.5) except the texels listed, at depth 0.
struct TapMap {
  static constexpr int kSize = 64;
  raster::DepthTarget target{kSize, kSize, raster::DepthFormat::d32f};
  TapMap() {
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) target.row<float>(y)[x] = 1.0f;
  }
  // Shadows the texel that the tap at disc point d (spread `spread`, centre st) reads.
  void shadow(glm::vec2 st, glm::vec2 d, float spread) {
    const glm::vec2 at = (st + d * spread) * float(kSize);
    target.row<float>(int(at.y))[int(at.x)] = 0.0f;
  }
};

tech::SampleContext centre(glm::vec2 frag = glm::vec2(10.5f, 20.5f)) {
  return tech::SampleContext{glm::vec2(0.5f), 0.5f, frag, glm::vec3(0.25f, 1.5f, -3.0f)};
}

tech::FilterParams tutorial_params(int taps) {
  tech::FilterParams p;
  p.taps = taps;
  p.spread = 20.0f / float(TapMap::kSize);  // taps 20 texels from the centre at most, each in its own texel
  p.tutorial = true;
  return p;
}

}  // namespace

// Worked by hand (in Python, each operation rounded to float with struct.pack('f'); sin taken in double on the
// float argument and rounded to float once): dot summed left to right, x 43758.5453, fract.
// seed (0.5, 0.5, 0.5), i 0: dot 68.1934051513671875, sin -0.79659003, product -34857.62109375, fract 0.37890625.
TEST(TutorialRandom, ReproducesValuesComputedByHand) {
  struct Case {
    glm::vec3 seed;
    int i;
    float random;
    int index;
  };
  const Case cases[] = {
      {{0.5f, 0.5f, 0.5f}, 0, 0.37890625f, 6},           // gl_FragCoord.xyy of pixel (0, 0)
      {{0.5f, 0.5f, 0.5f}, 3, 0.0439453125f, 0},
      {{100.5f, 37.5f, 37.5f}, 1, 0.48828125f, 7},
      {{1919.5f, 1079.5f, 1079.5f}, 2, 0.634765625f, 10},  // the top right pixel of a 1920x1080 frame
      {{1234.0f, -567.0f, 89.0f}, 0, 0.2734375f, 4},      // a world position in millimetres
      {{-2500.0f, 0.0f, 1500.0f}, 15, 0.078125f, 1},
  };
  for (const Case& c : cases) {
    // Through a volatile copy, so the compiler cannot fold sin() at build time: the run-time library's is tested.
    volatile float x = c.seed.x, y = c.seed.y, z = c.seed.z;
    const glm::vec3 seed(x, y, z);
    EXPECT_EQ(tech::tutorial_random(seed, c.i), c.random) << c.seed.x << " " << c.seed.y << " " << c.i;
    EXPECT_EQ(tech::tutorial_index(seed, c.i), c.index) << c.seed.x << " " << c.seed.y << " " << c.i;
  }
  // The seeds: gl_FragCoord.xyy, and the world position floored to the millimetre.
  EXPECT_EQ(tech::tutorial_pixel_seed(glm::vec2(100.5f, 37.5f)), glm::vec3(100.5f, 37.5f, 37.5f));
  EXPECT_EQ(tech::tutorial_world_seed(glm::vec3(1.2345f, -0.5665f, 0.0899f)), glm::vec3(1234.0f, -567.0f, 89.0f));
}

// fract(x) in float can be 1.0 (x a tiny negative number); the index stays in [0, 16) through the tutorial's % 16.
TEST(TutorialRandom, IndexStaysOnTheDisc) {
  EXPECT_EQ(tech::glsl_fract(-1e-9f), 1.0f);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int i = 0; i < 16; ++i) {
        const int k = tech::tutorial_index(tech::tutorial_pixel_seed(glm::vec2(x + 0.5f, y + 0.5f)), i);
        ASSERT_GE(k, 0);
        ASSERT_LT(k, 16);
      }
}

// Every subset of the taps shadowed: the tutorial variant returns 1 - 0.2·k as the tutorial's float fold
// computes it, clamped at 0 (16 taps: five shadowed leave 3e-8, six or more would go below zero).
TEST(TutorialPoisson, GivesOneMinusPointTwoPerShadowedTap) {
  for (int n : {4, 16}) {
    const tech::FilterParams p = tutorial_params(n);
    for (uint32_t mask = 0; mask < (1u << n); mask += n == 4 ? 1u : 257u) {  // 16 taps: 256 subsets
      TapMap map;
      for (int i = 0; i < n; ++i)
        if (mask >> i & 1u) map.shadow(glm::vec2(0.5f), tech::kPoissonDisk[size_t(i)], p.spread);
      const shading::Texture2D tex = shading::Texture2D::view(map.target);
      const tech::MapLookups maps = tech::map_lookups(tex, shading::Wrap::clamp_to_edge);
      const int k = std::popcount(mask);
      const float got = tech::PoissonFilter<tech::PoissonMode::fixed>{}(tech::Taps<false>{&maps}, centre(), p);
      const float want = tutorial_fold(k) > 0.0f ? tutorial_fold(k) : 0.0f;
      ASSERT_EQ(got, want) << n << " taps, mask " << mask;
      EXPECT_NEAR(got, std::max(0.0, 1.0 - 0.2 * k), 1e-6) << n << " taps, mask " << mask;
      // shadowlab's own variant averages the same taps.
      tech::FilterParams mean = p;
      mean.tutorial = false;
      EXPECT_EQ(tech::PoissonFilter<tech::PoissonMode::fixed>{}(tech::Taps<false>{&maps}, centre(), mean),
                float(n - k) / float(n));
    }
  }
  EXPECT_EQ(tutorial_fold(4), 0.20000003278255463f);  // the tutorial's "four shadowed taps leave 0.2"
  EXPECT_GT(tutorial_fold(5), 0.0f);                  // 2.98e-8: five of sixteen are not quite black
  EXPECT_LT(tutorial_fold(6), 0.0f);                  // clamped
}

// Stratified: tap i reads disc point int(16 · random(gl_FragCoord.xyy, i)) % 16. With one disc point's texel
// shadowed, the result counts the taps whose index is that point, for every pixel of a block and both seeds.
TEST(TutorialPoisson, StratifiedReadsTheTapsTheTutorialsRandomPicks) {
  const tech::FilterParams p = tutorial_params(4);
  size_t shadowed = 0, checked = 0;
  for (int point : {0, 6, 13}) {
    TapMap map;
    map.shadow(glm::vec2(0.5f), tech::kPoissonDisk[size_t(point)], p.spread);
    const shading::Texture2D tex = shading::Texture2D::view(map.target);
    const tech::MapLookups maps = tech::map_lookups(tex, shading::Wrap::clamp_to_edge);
    for (bool world : {false, true})
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
          tech::FilterParams q = p;
          q.stratify_world = world;
          tech::SampleContext c = centre(glm::vec2(x + 0.5f, y + 0.5f));
          c.world = glm::vec3(0.01f * x, 0.3f, -0.007f * y);
          const glm::vec3 seed = world ? tech::tutorial_world_seed(c.world) : tech::tutorial_pixel_seed(c.frag);
          int k = 0;
          for (int i = 0; i < 4; ++i) k += tech::tutorial_index(seed, i) == point;
          const float got = tech::PoissonFilter<tech::PoissonMode::stratified>{}(tech::Taps<false>{&maps}, c, q);
          ASSERT_EQ(got, tutorial_fold(k)) << "point " << point << " pixel " << x << "," << y << " world " << world;
          shadowed += k > 0;
          ++checked;
        }
  }
  EXPECT_GT(shadowed, checked / 8);  // the random does pick the shadowed point, often
}
