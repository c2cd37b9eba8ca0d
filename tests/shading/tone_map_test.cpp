// Exposure and tone mapping (shading/tone_map.h): EV100 against the luminance it saturates at, each operator's
// documented shape, and the names the scene file and command line read.
#include <gtest/gtest.h>

#include <cmath>

#include "shading/tone_map.h"

namespace {

using shading::ToneMap;

TEST(ToneMap, Ev100IsTheSaturatingLuminance) {
  // EV100 0 saturates at 1.2 cd/m²; every stop doubles it.
  EXPECT_FLOAT_EQ(shading::exposure_scale(0.0f), 1.0f / 1.2f);
  EXPECT_FLOAT_EQ(shading::exposure_scale(15.0f), 1.0f / (1.2f * 32768.0f));
  // ev100_mapping is the inverse: luminance l comes out as `value`.
  for (double l : {0.01, 1.0, 3183.0, 1e5}) {
    const float ev = shading::ev100_mapping(l, 0.18);
    EXPECT_NEAR(double(shading::exposure_scale(ev)) * l, 0.18, 1e-6) << l;
  }
}

TEST(ToneMap, NeutralKeepsBaseColoursAndCompressesHighlights) {
  // Below the knee (0.76) only the toe offset 0.04 is taken, for colours whose smallest channel is >= 0.08.
  const glm::vec3 c(0.5f, 0.3f, 0.1f);
  const glm::vec3 t = shading::tone_map(c, ToneMap::neutral);
  EXPECT_NEAR(t.r, 0.46f, 1e-6f);
  EXPECT_NEAR(t.g, 0.26f, 1e-6f);
  EXPECT_NEAR(t.b, 0.06f, 1e-6f);
  // Black stays black; grey stays grey; above the knee it rises monotonically towards 1 and never reaches it.
  EXPECT_EQ(shading::tone_map(glm::vec3(0.0f), ToneMap::neutral), glm::vec3(0.0f));
  float last = 0.0f;
  for (float v = 0.01f; v < 1000.0f; v *= 1.25f) {
    const glm::vec3 g = shading::tone_map(glm::vec3(v), ToneMap::neutral);
    EXPECT_EQ(g.r, g.g);
    EXPECT_EQ(g.g, g.b);
    EXPECT_GT(g.r, last) << v;
    EXPECT_LT(g.r, 1.0f) << v;
    last = g.r;
  }
  // A saturated highlight is desaturated towards white.
  const glm::vec3 h = shading::tone_map(glm::vec3(8.0f, 1.0f, 1.0f), ToneMap::neutral);
  EXPECT_GT(h.g / h.r, 1.0f / 8.0f);
}

TEST(ToneMap, AcesFittedIsAMonotonicSCurveIntoZeroOne) {
  EXPECT_EQ(shading::tone_map(glm::vec3(0.0f), ToneMap::aces), glm::vec3(0.0f));
  float last = 0.0f;
  for (float v = 0.01f; v < 100.0f; v *= 1.25f) {
    const float g = shading::tone_map(glm::vec3(v), ToneMap::aces).g;
    EXPECT_GE(g, last) << v;
    last = g;
  }
  EXPECT_GT(last, 0.99f);  // white at 100
  // Grey keeps its balance (each matrix row sums to 1) and middle grey 0.18 comes out at the fit's 0.1056:
  // (0.18 · 0.2045786 − 0.000090537) / (0.18 · 0.6099822 + 0.238081).
  const glm::vec3 grey = shading::tone_map(glm::vec3(0.18f), ToneMap::aces);
  EXPECT_NEAR(grey.g, 0.10559f, 1e-4f);
  EXPECT_NEAR(grey.r, grey.g, 1e-4f);
  EXPECT_NEAR(grey.b, grey.g, 1e-4f);
}

TEST(ToneMap, ClampPassesValuesAndClips) {
  EXPECT_EQ(shading::tone_map(glm::vec3(0.25f, 0.5f, 0.75f), ToneMap::clamp), glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(shading::tone_map(glm::vec3(-1.0f, 2.0f, 1.0f), ToneMap::clamp), glm::vec3(0.0f, 1.0f, 1.0f));
}

TEST(ToneMap, NamesRoundTrip) {
  for (ToneMap t : {ToneMap::neutral, ToneMap::aces, ToneMap::clamp})
    EXPECT_EQ(shading::parse_tone_map(shading::tone_map_name(t)), t);
  EXPECT_FALSE(shading::parse_tone_map("reinhard").has_value());
}

}  // namespace
