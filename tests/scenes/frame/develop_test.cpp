// The picture developed from the camera pass's luminance (scenes/frame/develop.h): metering, the background, and
// no banding: shading runs in float and is encoded to 8-bit sRGB once, so a smooth gradient steps by at most one
// code between neighbouring pixels (a frame shaded into a linear 8-bit buffer steps by up to 13 codes in the dark).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "raster/formats.h"
#include "raster/srgb8.h"
#include "scenes/frame/develop.h"
#include "scenes/frame/frame.h"
#include "tests/scenes/frame/floor_scene.h"
#include "tests/support.h"

namespace {

raster::ColorTarget uniform(int w, int h, glm::vec4 c) {
  raster::ColorTarget t(w, h, raster::ColorFormat::rgba32f);
  t.clear(c);
  return t;
}

// A 40 m square of floor seen straight from above (orthographic, filling the frame) under a point light 15 m
// over its centre: illuminance (direct, plus the light's ambient of ½ · 4π · 1000 / 3200 ≈ 2 lux) falls smoothly
// from 6.4 lux at the centre to 2.4 at the corners. No shadows, no specular.
scenes::Scene gradient_scene() {
  scenes::Scene s = testsupport::floor_seen_from_above({0.8f, 0.7f, 0.6f});
  scenes::Light lamp;
  lamp.type = scenes::LightType::point;
  lamp.position = {0, 15, 0};
  lamp.intensity = 1000.0f;
  lamp.shadow.technique = scenes::ShadowTechnique::none;
  s.lights.push_back(lamp);
  return s;
}

// The largest difference of one channel between horizontally or vertically neighbouring pixels, and the range of
// the green channel over the frame.
struct Steps {
  int largest = 0;
  int span = 0;
};
Steps steps(const raster::ColorTarget& c) {
  Steps s;
  int lo = 255, hi = 0;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) {
      const uint8_t* p = c.row8(y) + size_t(x) * 4;
      lo = std::min(lo, int(p[1])), hi = std::max(hi, int(p[1]));
      for (int ch = 0; ch < 3; ++ch) {
        if (x + 1 < c.width()) s.largest = std::max(s.largest, std::abs(int(p[ch]) - int(p[4 + ch])));
        if (y + 1 < c.height()) s.largest = std::max(s.largest, std::abs(int(p[ch]) - int(c.row8(y + 1)[size_t(x) * 4 + size_t(ch)])));
      }
    }
  s.span = hi - lo;
  return s;
}

}  // namespace

TEST(Develop, MeteringTakesTheLogAverageToMiddleGrey) {
  raster::ThreadPool pool(testsupport::test_threads());
  // Uniform 100 cd/m²: the log average and the 99th percentile are both 100; middle grey wins.
  const raster::ColorTarget t = uniform(8, 8, glm::vec4(100.0f, 100.0f, 100.0f, 1.0f));
  const float ev = frame::metered_ev100(t, shading::ToneMap::clamp, pool);
  EXPECT_NEAR(double(shading::exposure_scale(ev)) * 100.0, 0.18, 1e-5);
  // Undrawn pixels (alpha 0) and unlit ones do not count; nothing lit: EV100 0.
  EXPECT_EQ(frame::metered_ev100(uniform(4, 4, glm::vec4(5.0f, 5.0f, 5.0f, 0.0f)), shading::ToneMap::clamp, pool), 0.0f);
  EXPECT_EQ(frame::metered_ev100(uniform(4, 4, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)), shading::ToneMap::clamp, pool), 0.0f);
}

TEST(Develop, MeteringKeepsTheBrightestPercentUnderOne) {
  raster::ThreadPool pool(testsupport::test_threads());
  // Half the pixels at 1, half at 10000: the log average (100) would put the bright half at 18; the 99th
  // percentile caps it where the tone map shows 95 % of white: 0.95 for clamp, more for the curves.
  raster::ColorTarget t = uniform(10, 10, glm::vec4(1.0f, 1.0f, 1.0f, 1.0f));
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 10; ++x) t.write(x, y, glm::vec4(10000.0f, 10000.0f, 10000.0f, 1.0f));
  for (const shading::ToneMap m : {shading::ToneMap::clamp, shading::ToneMap::neutral, shading::ToneMap::aces}) {
    const double exposed = double(shading::exposure_scale(frame::metered_ev100(t, m, pool))) * 10000.0;
    EXPECT_NEAR(exposed, double(frame::highlight_limit(m)), 1e-3 * exposed);
    EXPECT_NEAR(shading::tone_map(glm::vec3(float(exposed)), m).g, 0.95f, 1e-3f);
  }
  EXPECT_NEAR(frame::highlight_limit(shading::ToneMap::clamp), 0.95f, 1e-5f);
  EXPECT_GT(frame::highlight_limit(shading::ToneMap::neutral), 1.5f);
}

TEST(Develop, BackgroundWhereNothingWasDrawnIsShownAsGiven) {
  raster::ThreadPool pool(testsupport::test_threads());
  raster::ColorTarget r = uniform(4, 3, glm::vec4(0.0f));
  r.write(1, 1, glm::vec4(1.2f, 1.2f, 1.2f, 1.0f));  // EV100 0 saturates at 1.2: exposed 1, clamp: white
  const scenes::Background b{{0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}};
  const raster::ColorTarget c = frame::develop(r, 0.0f, shading::ToneMap::clamp, b, pool);
  ASSERT_TRUE(c.srgb());
  auto px = [&](int x, int y) {
    const uint8_t* p = c.row8(y) + size_t(x) * 4;
    return glm::ivec4(p[0], p[1], p[2], p[3]);
  };
  EXPECT_EQ(px(0, 0), glm::ivec4(255, 0, 0, 255));  // bottom row: `bottom`
  EXPECT_EQ(px(3, 2), glm::ivec4(0, 0, 255, 255));  // top row: `top`
  const int half = int(std::nearbyint(raster::srgb_encode(0.5f) * 255.0f));
  EXPECT_EQ(px(0, 1), glm::ivec4(half, 0, half, 255));  // halfway, mixed in linear, then encoded
  EXPECT_EQ(px(1, 1), glm::ivec4(255, 255, 255, 255));
  // The tutorial's clear colour comes out as the old frames showed it: linear 0.4 blue, sRGB-encoded.
  const raster::ColorTarget tut = frame::develop(r, 0.0f, shading::ToneMap::clamp, *scenes::named_background("tutorial"), pool);
  EXPECT_EQ(tut.row8(0)[2], uint8_t(std::nearbyint(raster::srgb_encode(0.4f) * 255.0f)));
}

TEST(Develop, SmoothGradientHasNoBands) {
  const scenes::Scene scene = gradient_scene();
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig o;
  o.width = 320, o.height = 180;
  const frame::Frame metered = frame::render_frame(scene, o, renderer);
  // Metered, and two and a half stops darker, where an 8-bit linear buffer's codes are sRGB codes apart.
  for (const float stops : {0.0f, 2.5f})
    for (const shading::ToneMap t : {shading::ToneMap::neutral, shading::ToneMap::aces, shading::ToneMap::clamp}) {
      SCOPED_TRACE(std::string(shading::tone_map_name(t)) + ", " + std::to_string(stops) + " stops under");
      o.exposure = scenes::Exposure{metered.ev100 + stops};
      o.tone_map = t;
      const Steps s = steps(frame::render_frame(scene, o, renderer).color);
      EXPECT_LE(s.largest, 1);
      EXPECT_GE(s.span, 8) << "the gradient should span several codes";
    }
}

// develop() stores, pixel for pixel, the bytes that ColorTarget::write stores for the tone-mapped value in an sRGB
// target (it encodes through raster/srgb8.h's thresholds instead of a pow per channel), dithered by at most a
// quarter of a code: a byte is write()'s, or its neighbour only where the exact encoded value lies within a
// quarter code (plus a little for the linear step inside a code) of the edge between them; black and white are
// exact. Luminances over 24 stops, coloured, with undrawn pixels between them, every operator, at any thread
// count (one result for all).
TEST(Develop, StoresWhatAnSrgbTargetWriteStoresWithinAQuarterCode) {
  const int w = 97, h = 61;
  raster::ColorTarget r(w, h, raster::ColorFormat::rgba32f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float l = std::exp2(-12.0f + 24.0f * float(x + w * y) / float(w * h));
      r.write(x, y, (x + y) % 7 == 0 ? glm::vec4(0.0f) : glm::vec4(l, 0.6f * l, 0.2f * l + 1e-4f, 1.0f));
    }
  const scenes::Background b{{0.1f, 0.3f, 0.9f}, {0.8f, 0.7f, 0.2f}};
  for (const shading::ToneMap t : {shading::ToneMap::neutral, shading::ToneMap::aces, shading::ToneMap::clamp}) {
    raster::ThreadPool one(0);
    const raster::ColorTarget first = frame::develop(r, 1.5f, t, b, one);
    raster::ThreadPool pool(3);
    const raster::ColorTarget c = frame::develop(r, 1.5f, t, b, pool);
    size_t moved = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        ASSERT_TRUE(std::equal(c.row8(y) + 4 * x, c.row8(y) + 4 * x + 4, first.row8(y) + 4 * x)) << x << ", " << y;
        const glm::vec4 p = r.read(x, y);
        const float s = float(y) / float(h - 1);
        const glm::vec3 v = p.a > 0.0f ? shading::tone_map(glm::vec3(p) * shading::exposure_scale(1.5f), t)
                                       : b.bottom * (1.0f - s) + b.top * s;
        for (int ch = 0; ch < 3; ++ch) {
          const int got = c.row8(y)[4 * x + ch];
          if (!(v[ch] > 0.0f) || v[ch] >= 1.0f) {
            ASSERT_EQ(got, v[ch] >= 1.0f ? 255 : 0) << x << ", " << y;
            continue;
          }
          const float e = raster::srgb_encode(v[ch]) * 255.0f;
          ASSERT_GE(got, int(std::lround(e - 0.27f))) << x << ", " << y << ", " << ch;
          ASSERT_LE(got, int(std::lround(e + 0.27f))) << x << ", " << y << ", " << ch;
          moved += got != int(std::lround(e));
        }
        ASSERT_EQ(c.row8(y)[4 * x + 3], 255);
      }
    EXPECT_GT(moved, size_t(0)) << "no pixel was dithered";
  }
}

// The dither is one value for the three channels: a grey gradient stays grey in every pixel (independent noise
// per channel would tint it), and a ramp across one code boundary, slow enough to band, mixes the two codes over
// the rows instead of one hard edge, every pixel one of the two.
TEST(Develop, DitherIsUntintedAndBreaksAHardEdge) {
  const int w = 256, h = 64;
  raster::ColorTarget r(w, h, raster::ColorFormat::rgba32f);
  raster::Srgb8Encoder srgb8;
  // From the middle of code 40 to the middle of code 41 (in linear light, between the encoder's thresholds): the
  // edge between them in the middle, half a code on either side.
  const float lo = 0.5f * (srgb8.threshold(40) + srgb8.threshold(41));
  const float top = 0.5f * (srgb8.threshold(41) + srgb8.threshold(42));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = lo + (top - lo) * (float(x) + 0.5f) / float(w);
      r.write(x, y, glm::vec4(v, v, v, 1.0f));
    }
  raster::ThreadPool pool(testsupport::test_threads());
  const raster::ColorTarget c = frame::develop(r, shading::ev100_mapping(1.0, 1.0), shading::ToneMap::clamp,
                                               scenes::Background{}, pool);
  int mixed_columns = 0;
  for (int x = 0; x < w; ++x) {
    bool has40 = false, has41 = false;
    for (int y = 0; y < h; ++y) {
      const uint8_t* p = c.row8(y) + 4 * x;
      ASSERT_EQ(p[0], p[1]) << x << ", " << y;
      ASSERT_EQ(p[1], p[2]) << x << ", " << y;
      ASSERT_GE(p[0], 40);
      ASSERT_LE(p[0], 41);
      has40 |= p[0] == 40, has41 |= p[0] == 41;
    }
    mixed_columns += has40 && has41;
  }
  // Within a quarter code of the edge: 64 columns either side of x = 128 can mix (at the fringes rarely).
  EXPECT_GE(mixed_columns, 80);
  EXPECT_LE(mixed_columns, 130);
}

// The metered EV100 is exactly the one of the plain computation (log2 summed row by row, the 99th percentile by
// std::nth_element over every lit luminance) on a frame of many distinct, repeated and tiny luminances.
TEST(Develop, MeteringIsExactlyThePlainComputation) {
  const int w = 203, h = 117;
  raster::ColorTarget r(w, h, raster::ColorFormat::rgba32f);
  uint32_t seed = 12345;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t n = next();
      const float l = n % 13 == 0 ? 1e-40f : n % 5 == 0 ? 3.0f : std::exp2(float(n >> 8) / float(1 << 24) * 40.0f - 20.0f);
      r.write(x, y, n % 11 == 0 ? glm::vec4(l, l, l, 0.0f) : glm::vec4(l, 0.5f * l, 2.0f * l, 1.0f));
    }
  std::vector<float> all;
  double sum = 0.0;
  for (int y = 0; y < h; ++y) {
    double row = 0.0;
    for (int x = 0; x < w; ++x) {
      const glm::vec4 p = r.read(x, y);
      const float l = shading::luminance(glm::vec3(p));
      if (!(p.a > 0.0f) || !(l > 0.0f) || !std::isfinite(l)) continue;
      all.push_back(l);
      row += std::log2(double(l));
    }
    sum += row;
  }
  const auto p99 = all.begin() + std::ptrdiff_t(double(all.size() - 1) * 0.99);
  std::nth_element(all.begin(), p99, all.end());
  for (const shading::ToneMap t : {shading::ToneMap::neutral, shading::ToneMap::clamp}) {
    const float expected = std::max(shading::ev100_mapping(std::exp2(sum / double(all.size())), 0.18),
                                    shading::ev100_mapping(double(*p99), double(frame::highlight_limit(t))));
    for (const int threads : {0, 2}) {
      raster::ThreadPool pool(threads);
      EXPECT_EQ(frame::metered_ev100(r, t, pool), expected);
    }
  }
}

// A frame handed back to the cache (frame::recycle) lends its radiance and picture to the next frame of its size:
// that frame is byte for byte the one rendered into fresh targets, even after a frame of another size and with
// the old contents still there (a brighter lamp, then the gradient again).
TEST(Develop, RecycledTargetsGiveTheSameFrame) {
  const scenes::Scene scene = gradient_scene();
  scenes::Scene bright = scene;
  bright.lights[0].intensity = 50000.0f;
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig config;
  config.width = 96, config.height = 54;
  const frame::Frame fresh = frame::render_frame(scene, config, renderer);
  frame::FrameCache cache;
  frame::FrameConfig other = config;
  other.width = 64;
  frame::recycle(frame::render_frame(scene, other, renderer, &cache), cache);  // another size: not reused
  frame::recycle(frame::render_frame(bright, config, renderer, &cache), cache);
  ASSERT_TRUE(cache.radiance && cache.picture);
  const float* kept = cache.radiance->row32f(0);
  const frame::Frame again = frame::render_frame(scene, config, renderer, &cache);
  EXPECT_EQ(again.radiance.row32f(0), kept);  // the same storage, cleared and drawn again
  EXPECT_FALSE(cache.radiance || cache.picture);
  for (int y = 0; y < config.height; ++y) {
    EXPECT_TRUE(std::equal(fresh.color.row8(y), fresh.color.row8(y) + config.width * 4, again.color.row8(y))) << y;
    EXPECT_TRUE(std::equal(fresh.radiance.row32f(y), fresh.radiance.row32f(y) + config.width * 4,
                           again.radiance.row32f(y), [](float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); })) << y;
  }
  EXPECT_EQ(again.ev100, fresh.ev100);
}
