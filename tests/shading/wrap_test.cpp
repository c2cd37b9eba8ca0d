// Every wrap mode of CONVENTIONS at and beyond each edge, for LINEAR and NEAREST, on both axes; legacy clamp
// mixes the edge texel with the border colour. Expected values are worked out by hand from GL's rules.
#include <gtest/gtest.h>

#include <vector>

#include "shading/lookup.h"
#include "shading/wrap.h"

namespace {

using shading::Filter;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;
using shading::Wrap;

// Texels 1, 2, 4, 8 along the axis under test; border colour 100.
constexpr float kBorder = 100.0f;

struct Case {
  float coord;
  float edge, border, clamp, repeat, mirrored;
};

// LINEAR, W = 4: u = 4s − 0.5.
//  s = 0:     u = −0.5, taps −1, 0 (½ each).  edge: 1. border: ½·100 + ½·1. clamp: s stays 0 → as border.
//             repeat: −1 → 3: ½·8 + ½·1. mirrored: −1 → 0: 1.
//  s = −0.25: u = −1.5, taps −2, −1.  edge 1; border 100; clamp: s → 0, still 50.5; repeat: 2, 3 → 6;
//             mirrored: −2 → 1, −1 → 0 → 1.5.
//  s = 1:     u = 3.5, taps 3, 4. edge 8; border ½·8 + ½·100; clamp 54; repeat: 4 → 0: 4.5; mirrored: 4 → 3: 8.
//  s = 1.25:  u = 4.5, taps 4, 5. edge 8; border 100; clamp: s → 1: 54; repeat: 0, 1 → 1.5; mirrored: 3, 2 → 6.
//  s = 2.125: u = 8, tap 8 alone (weight 0 on 9). repeat: 8 → 0: 1; mirrored: 8 → 0: 1.
const Case kLinear[] = {
    {0.0f, 1.0f, 50.5f, 50.5f, 4.5f, 1.0f},    {-0.25f, 1.0f, 100.0f, 50.5f, 6.0f, 1.5f},
    {1.0f, 8.0f, 54.0f, 54.0f, 4.5f, 8.0f},    {1.25f, 8.0f, 100.0f, 54.0f, 1.5f, 6.0f},
    {2.125f, 8.0f, 100.0f, 54.0f, 1.0f, 1.0f},
};

// NEAREST: i = floor(4s).
//  s = −0.01: i = −1. edge 1; border 100; clamp: s → 0, i = 0: 1; repeat: 3 → 8; mirrored: 0 → 1.
//  s = 1:     i = 4.  edge 8; border 100; clamp: s = 1 reads the edge texel: 8; repeat: 0 → 1; mirrored: 3 → 8.
//  s = 1.3:   i = 5.  edge 8; border 100; clamp 8; repeat: 1 → 2; mirrored: 5 → 2 → 4.
const Case kNearest[] = {
    {-0.01f, 1.0f, 100.0f, 1.0f, 8.0f, 1.0f},
    {1.0f, 8.0f, 100.0f, 8.0f, 1.0f, 8.0f},
    {1.3f, 8.0f, 100.0f, 8.0f, 2.0f, 4.0f},
};

float expected(const Case& c, Wrap w) {
  switch (w) {
    case Wrap::clamp_to_edge: return c.edge;
    case Wrap::clamp_to_border: return c.border;
    case Wrap::clamp: return c.clamp;
    case Wrap::repeat: return c.repeat;
    case Wrap::mirrored_repeat: return c.mirrored;
  }
  return 0.0f;
}

constexpr Wrap kModes[] = {Wrap::clamp_to_edge, Wrap::clamp_to_border, Wrap::clamp, Wrap::repeat,
                           Wrap::mirrored_repeat};

void check_axis(Filter filter, const Case* cases, size_t n) {
  const std::vector<float> v = {1, 2, 4, 8};
  const Texture2D row = Texture2D::from_floats(4, 1, TexelFormat::r32f, 1, v);
  const Texture2D column = Texture2D::from_floats(1, 4, TexelFormat::r32f, 1, v);
  for (Wrap w : kModes) {
    for (size_t k = 0; k < n; ++k) {
      const Case& c = cases[k];
      Sampler s = Sampler::plain(filter);
      s.border_color = glm::vec4(kBorder);
      // s axis under test; t uses a different mode to show the axes are independent (a 1-texel axis reads
      // texel 0 under repeat at any coordinate).
      s.wrap_s = w;
      s.wrap_t = Wrap::repeat;
      EXPECT_EQ(shading::texture(row, s, glm::vec2(c.coord, 0.3f)).r, expected(c, w))
          << "s axis, " << shading::to_string(w) << ", s = " << c.coord;
      // Mirror image: the t axis of a column texture, bottom and top edges.
      s.wrap_t = w;
      s.wrap_s = Wrap::repeat;
      EXPECT_EQ(shading::texture(column, s, glm::vec2(0.3f, c.coord)).r, expected(c, w))
          << "t axis, " << shading::to_string(w) << ", t = " << c.coord;
    }
  }
}

TEST(Wrap, LinearAtAndBeyondEachEdge) { check_axis(Filter::linear, kLinear, std::size(kLinear)); }
TEST(Wrap, NearestAtAndBeyondEachEdge) { check_axis(Filter::nearest, kNearest, std::size(kNearest)); }

TEST(Wrap, LegacyClampMixesTheEdgeTexelWithTheBorderHalfAndHalf) {
  // With a 2 × 2 texture and LINEAR, the corner s = t = 0 under GL_CLAMP reads ¼ edge texel, ¾ border.
  const Texture2D t = Texture2D::from_floats(2, 2, TexelFormat::r32f, 1, std::vector<float>{4, 0, 0, 0});
  Sampler s = Sampler::plain(Filter::linear, Wrap::clamp);
  s.border_color = glm::vec4(8.0f);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.0f, 0.0f)).r, 0.25f * 4.0f + 0.75f * 8.0f);
  EXPECT_EQ(shading::texture(t, s, glm::vec2(-7.0f, -7.0f)).r, 7.0f);  // far beyond: still the corner mix
  s.wrap_s = s.wrap_t = Wrap::clamp_to_edge;
  EXPECT_EQ(shading::texture(t, s, glm::vec2(0.0f, 0.0f)).r, 4.0f);
}

TEST(Wrap, MirroredRepeatIndexSequence) {
  // GL: (n − 1) − mirror((i mod 2n) − n). For n = 3: 0 1 2 2 1 0 | 0 1 2 …, and mirrored below 0.
  const int expected_pos[] = {0, 1, 2, 2, 1, 0, 0, 1, 2};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(shading::wrap_index(Wrap::mirrored_repeat, i, 3), expected_pos[i]) << i;
  const int expected_neg[] = {0, 1, 2, 2, 1, 0, 0};  // i = −1 … −7
  for (int k = 0; k < 7; ++k)
    EXPECT_EQ(shading::wrap_index(Wrap::mirrored_repeat, -1 - k, 3), expected_neg[k]) << -1 - k;
  EXPECT_EQ(shading::wrap_index(Wrap::repeat, -1, 3), 2);
  EXPECT_EQ(shading::wrap_index(Wrap::repeat, -4, 3), 2);
  EXPECT_EQ(shading::wrap_index(Wrap::clamp_to_border, 3, 3), shading::kBorder);
  EXPECT_EQ(shading::wrap_index(Wrap::clamp_to_edge, -5, 3), 0);
}

TEST(Wrap, BorderColourIsClampedForUnormFormatsAndSwizzledForRedFormats) {
  Texture2D rgba8(1, 1, TexelFormat::rgba8);
  Sampler s = Sampler::plain(Filter::nearest, Wrap::clamp_to_border);
  s.border_color = glm::vec4(2.0f, -1.0f, 0.5f, 1.0f);
  EXPECT_EQ(shading::texture(rgba8, s, glm::vec2(-1.0f, 0.5f)), glm::vec4(1.0f, 0.0f, 0.5f, 1.0f));
  Texture2D r32f(1, 1, TexelFormat::r32f);
  EXPECT_EQ(shading::texture(r32f, s, glm::vec2(-1.0f, 0.5f)), glm::vec4(2.0f, 0.0f, 0.0f, 1.0f));
  Texture2D rgba32f(1, 1, TexelFormat::rgba32f);
  EXPECT_EQ(shading::texture(rgba32f, s, glm::vec2(-1.0f, 0.5f)), s.border_color);
}

TEST(Wrap, NonFiniteCoordinatesStayInRange) {
  const Texture2D t = Texture2D::from_floats(2, 1, TexelFormat::r32f, 1, std::vector<float>{3, 5});
  const Sampler s = Sampler::plain(Filter::linear, Wrap::repeat);
  for (float c : {1e30f, -1e30f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    const float v = shading::texture(t, s, glm::vec2(c, 0.5f)).r;
    EXPECT_TRUE(v >= 3.0f && v <= 5.0f) << c << " -> " << v;
  }
}

}  // namespace
