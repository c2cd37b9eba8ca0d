// Depth: interpolation from the window-space plane, quantisation per format, the eight depth functions (the
// run-time comparison against GL's definition value by value, and through every back end: depth-only, quad,
// pair, early and late test), depth write mask, polygon offset (factor and units) as CONVENTIONS defines it.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "raster/setup.h"
#include "tests/raster/raster_test_util.h"
#include "tests/support.h"

using namespace raster;

namespace {
std::vector<glm::vec4> quad_at(float z_ndc) {
  return {{-1, -1, z_ndc, 1}, {1, -1, z_ndc, 1}, {1, 1, z_ndc, 1}, {-1, -1, z_ndc, 1}, {1, 1, z_ndc, 1}, {-1, 1, z_ndc, 1}};
}
void draw(Renderer& r, DepthTarget& d, const std::vector<glm::vec4>& v, const DrawState& s = {}) {
  r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v));
}

constexpr DepthFunc kFuncs[] = {DepthFunc::never,   DepthFunc::less,     DepthFunc::equal,  DepthFunc::lequal,
                                DepthFunc::greater, DepthFunc::notequal, DepthFunc::gequal, DepthFunc::always};

// GL's depth test as the specification words it: the fragment passes when `frag FUNC stored`. With a NaN
// operand C++'s operators are false, except !=, which is true: the same as GL's (and llvmpipe's) rule.
template <class T>
bool gl_passes(DepthFunc f, T frag, T stored) {
  switch (f) {
    case DepthFunc::never: return false;
    case DepthFunc::less: return frag < stored;
    case DepthFunc::equal: return frag == stored;
    case DepthFunc::lequal: return frag <= stored;
    case DepthFunc::greater: return frag > stored;
    case DepthFunc::notequal: return frag != stored;
    case DepthFunc::gequal: return frag >= stored;
    case DepthFunc::always: return true;
  }
  return false;
}

// The eight pairs in lanes, DepthCompare's SIMD and scalar forms and the compile-time depth_compare<Func>
// against gl_passes, lane by lane.
template <class Vec, class T>
void check_compare(DepthFunc f, const T (&frag)[8], const T (&stored)[8]) {
  const Vec a = Vec::load(frag), b = Vec::load(stored);
  const DepthCompare compare(f);
  const unsigned simd_bits = compare(a, b).bits();
  unsigned fixed_bits = 0;
  [&]<size_t... I>(std::index_sequence<I...>) {
    ((kFuncs[I] == f ? void(fixed_bits = depth_compare<kFuncs[I]>(a, b).bits()) : void()), ...);
  }(std::make_index_sequence<8>{});
  for (int l = 0; l < 8; ++l) {
    const bool expect = gl_passes(f, frag[l], stored[l]);
    EXPECT_EQ(bool(simd_bits >> l & 1u), expect) << "func " << int(f) << " lane " << l << ": " << frag[l] << " vs " << stored[l];
    EXPECT_EQ(compare.test(frag[l], stored[l]), expect) << "func " << int(f) << " scalar " << frag[l] << " vs " << stored[l];
    EXPECT_EQ(bool(fixed_bits >> l & 1u), expect) << "func " << int(f) << " fixed lane " << l;
  }
}

// A flat white shader for the shaded back ends: the quad path or the wide one (kWide), with the early depth test
// or, when it writes `depth` as the fragment depth (kDepth), the late one.
template <bool kWide, bool kDepth>
struct FlatShader {
  using Vertex = glm::vec4;
  struct Varyings {
    float unused;
  };
  static constexpr bool kWritesDepth = kDepth;
  float depth = 0.0f;
  glm::vec4 vertex(const Vertex& v, Varyings& o) const {
    o.unused = 0.0f;
    return v;
  }
  void fragment(const QuadIn<Varyings>&, QuadOut& out) const {
    for (int l = 0; l < 4; ++l) out.color[l] = glm::vec4(1.0f), out.depth[l] = depth;
  }
  void fragment_pair(const QuadPairIn<Varyings>&, QuadPairOut& out) const
    requires kWide
  {
    for (auto& c : out.color) c = simd::VecF32::splat(1.0f);
    out.depth = simd::VecF32::splat(depth);
  }
};
}  // namespace

TEST(Depth, QuantisationPerFormat) {
  Renderer r(testsupport::test_threads());
  for (float z_ndc : {-1.0f, -0.3f, 0.0f, 0.123456f, 0.999f, 1.0f}) {
    const float zw = std::fma(z_ndc, 0.5f, 0.5f);
    DepthTarget d16(9, 7, DepthFormat::d16), d24(9, 7, DepthFormat::d24), d32(9, 7, DepthFormat::d32f);
    DrawState s;
    s.depth_func = DepthFunc::always;
    for (DepthTarget* d : {&d16, &d24, &d32}) draw(r, *d, quad_at(z_ndc), s);
    EXPECT_EQ(d16.raw(4, 3), uint32_t(std::nearbyint(double(zw) * 65535.0))) << z_ndc;
    EXPECT_NEAR(double(d24.raw(4, 3)), std::nearbyint(double(zw) * 16777215.0), 1.0) << z_ndc;
    EXPECT_EQ(d32.value(4, 3), zw) << z_ndc;
  }
}

// A plane z_w = 0.2 + 0.01·x + 0.003·y (window units) is reproduced at every pixel centre within float rounding.
TEST(Depth, PlaneInterpolationAtPixelCentres) {
  Renderer r(testsupport::test_threads());
  const int W = 50, H = 40;
  auto zw = [](double x, double y) { return 0.2 + 0.01 * x + 0.003 * y; };
  auto v = [&](double x, double y) { return rtest::win_to_clip(x, y, W, H, zw(x, y) * 2 - 1); };
  std::vector<glm::vec4> tri = {v(0, 0), v(W, 0), v(W, H), v(0, 0), v(W, H), v(0, H)};
  DepthTarget d(W, H, DepthFormat::d32f);
  draw(r, d, tri);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) ASSERT_NEAR(d.value(x, y), zw(x + 0.5, y + 0.5), 2e-7) << x << "," << y;
}

TEST(Depth, EveryDepthFunction) {
  Renderer r(0);
  struct Case { DepthFunc f; bool at_less, at_equal, at_greater; };
  const Case cases[] = {{DepthFunc::never, false, false, false},   {DepthFunc::less, true, false, false},
                        {DepthFunc::equal, false, true, false},    {DepthFunc::lequal, true, true, false},
                        {DepthFunc::greater, false, false, true},  {DepthFunc::notequal, true, false, true},
                        {DepthFunc::gequal, false, true, true},    {DepthFunc::always, true, true, true}};
  for (DepthFormat fmt : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    for (const Case& c : cases) {
      // Stored depth: 0.5 everywhere. Then draw at z_w = 0.25 (less), 0.5 (equal), 0.75 (greater).
      for (int which = 0; which < 3; ++which) {
        DepthTarget d(8, 8, fmt);
        DrawState fill;
        fill.depth_func = DepthFunc::always;
        draw(r, d, quad_at(0.0f), fill);
        const uint32_t before = d.raw(3, 3);
        DrawState s;
        s.depth_func = c.f;
        draw(r, d, quad_at(which == 0 ? -0.5f : which == 1 ? 0.0f : 0.5f), s);
        const bool expect = which == 0 ? c.at_less : which == 1 ? c.at_equal : c.at_greater;
        const bool written = which == 1 ? expect : d.raw(3, 3) != before;
        EXPECT_EQ(written, expect) << to_string(fmt) << " func " << int(c.f) << " case " << which;
      }
    }
  }
}

TEST(Depth, WriteMaskAndDisabledTestLeaveBufferAlone) {
  Renderer r(0);
  DepthTarget d(8, 8, DepthFormat::d32f);
  DrawState s;
  s.depth_write = false;
  draw(r, d, quad_at(0.0f), s);
  EXPECT_EQ(d.value(2, 2), 1.0f);
  s = DrawState{};
  s.depth_test = false;  // GL: no depth test means no depth write either
  draw(r, d, quad_at(0.0f), s);
  EXPECT_EQ(d.value(2, 2), 1.0f);
}

// Polygon offset o = m·factor + r·units, m = max(|dz/dx|, |dz/dy|): checked on a sloped plane per format.
TEST(Depth, PolygonOffsetFactorAndUnits) {
  Renderer r(0);
  const int W = 32, H = 32;
  const double dzdx = 0.004, dzdy = -0.001;
  auto zw = [&](double x, double y) { return 0.4 + dzdx * x + dzdy * y; };
  auto v = [&](double x, double y) { return rtest::win_to_clip(x, y, W, H, zw(x, y) * 2 - 1); };
  std::vector<glm::vec4> tri = {v(0, 0), v(W, 0), v(W, H), v(0, 0), v(W, H), v(0, H)};
  for (DepthFormat fmt : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    for (auto [factor, units] : {std::pair{0.0f, 0.0f}, {2.0f, 0.0f}, {0.0f, 4.0f}, {1.5f, 3.0f}, {-1.0f, -2.0f}}) {
      DepthTarget d(W, H, fmt);
      DrawState s;
      s.polygon_offset = {factor, units};
      draw(r, d, tri, s);
      const double x = 10.5, y = 20.5;
      const float zmax = float(std::max({zw(0, 0), zw(W, 0), zw(W, H), zw(0, H)}));
      // Each of the two triangles has its own largest vertex depth; both contain zw(W, 0) = the maximum.
      const double rr = polygon_offset_r(fmt, zmax);
      EXPECT_NEAR(rr, fmt == DepthFormat::d16 ? 2.0 / 65535 : fmt == DepthFormat::d24 ? 2.0 / 16777215 : std::ldexp(1.0, -24), 1e-12);
      const double expected = zw(x, y) + std::max(std::abs(dzdx), std::abs(dzdy)) * factor + rr * units;
      const double tol = fmt == DepthFormat::d16 ? 0.51 / 65535 : fmt == DepthFormat::d24 ? 1.01 / 16777215 : 3e-7;
      EXPECT_NEAR(d.value(10, 20), expected, tol) << to_string(fmt) << " factor " << factor << " units " << units;
    }
  }
}

// DepthCompare, the run-time depth test, on values of every format's representation, equal values included, and
// on d32f's NaN, ±0 and infinities: SIMD, scalar and compile-time forms all give GL's answer.
TEST(Depth, RunTimeCompareMatchesGL) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const int32_t ifrag[3][8] = {{0, 1, 2, 65535, 65534, 16777215, 7, 8},
                               {0, 0, 3, 65535, 65535, 16777214, 7, 9},
                               {1, 0, 2, 0, 65535, 16777215, 8, 8}};
  const int32_t istored[3][8] = {{0, 0, 2, 65535, 65535, 16777215, 8, 7},
                                 {1, 0, 2, 65534, 65535, 16777215, 7, 8},
                                 {1, 1, 1, 65535, 0, 16777214, 7, 8}};
  const float ffrag[3][8] = {{0.5f, 0.25f, 0.75f, 0.0f, -0.0f, nan, 0.5f, nan},
                             {1.0f, 0.0f, -0.0f, inf, -inf, 0.3f, nan, 1.0f},
                             {0.1f, std::nextafter(0.5f, 1.0f), 0.5f, 1.0f, 0.0f, -0.0f, 0.0f, nan}};
  const float fstored[3][8] = {{0.5f, 0.5f, 0.5f, -0.0f, 0.0f, 0.5f, nan, nan},
                               {1.0f, 0.0f, -0.0f, 1.0f, 0.0f, 0.3f, 0.0f, 1.0f},
                               {0.2f, 0.5f, std::nextafter(0.5f, 1.0f), 1.0f, 0.0f, -0.0f, nan, 0.0f}};
  for (DepthFunc f : kFuncs)
    for (int k = 0; k < 3; ++k) {
      check_compare<simd::VecI32>(f, ifrag[k], istored[k]);
      check_compare<simd::VecF32>(f, ffrag[k], fstored[k]);
    }
}

// Every depth function through every back end and format, on the fragment's depth below, equal to and above the
// stored one, and on d32f also NaN, +0 against -0 and the reverse: a pixel passes (its colour is written, for
// shaded draws) and its depth is written exactly when GL's rule says so.
TEST(Depth, EveryDepthFunctionEveryBackEnd) {
  Renderer r(0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  enum Path { depth_only, quad_early, pair_early, quad_late, pair_late };
  struct Case { float stored, frag; };
  // The fragment's depth comes from the plane (a constant-depth quad) on the early paths, from the shader on
  // the late ones; depth-only and early-tested fragments are clamped, so cannot be NaN or -0.
  const std::vector<Case> common = {{0.5f, 0.25f}, {0.5f, 0.5f}, {0.5f, 0.75f}, {0.0f, 1.0f}, {1.0f, 0.0f}};
  const std::vector<Case> d32f_plane = {{nan, 0.5f}, {-0.0f, 0.0f}};
  const std::vector<Case> d32f_shader = {{nan, 0.5f}, {-0.0f, 0.0f}, {0.5f, nan}, {0.0f, -0.0f}, {nan, nan}};
  for (DepthFormat fmt : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    for (Path path : {depth_only, quad_early, pair_early, quad_late, pair_late})
      for (DepthFunc f : kFuncs) {
        const bool late = path == quad_late || path == pair_late;
        std::vector<Case> cases = common;
        if (fmt == DepthFormat::d32f) {
          const auto& extra = late ? d32f_shader : d32f_plane;
          cases.insert(cases.end(), extra.begin(), extra.end());
        }
        for (const Case& c : cases) {
          const int W = 16, H = 8;
          DepthTarget d(W, H, fmt), expect_frag(1, 1, fmt), expect_stored(1, 1, fmt);
          d.clear(c.stored);
          expect_frag.clear(c.frag);  // the stored form of the fragment's depth (NaN and -0 kept on d32f)
          expect_stored.clear(c.stored);
          ColorTarget color(W, H, ColorFormat::rgba8);
          color.clear(glm::vec4(0.0f));
          DrawState s;
          s.depth_func = f;
          const auto quad = quad_at(late ? 0.0f : c.frag * 2.0f - 1.0f);  // exact for the values above
          const std::span<const glm::vec4> v(quad);
          const RenderTargets both{&d, &color};
          switch (path) {
            case depth_only: r.draw(RenderTargets{&d}, s, ClipSpaceDepthShader{}, v); break;
            case quad_early: r.draw(both, s, FlatShader<false, false>{}, v); break;
            case pair_early: r.draw(both, s, FlatShader<true, false>{}, v); break;
            case quad_late: r.draw(both, s, FlatShader<false, true>{c.frag}, v); break;
            case pair_late: r.draw(both, s, FlatShader<true, true>{c.frag}, v); break;
          }
          const uint32_t frag = expect_frag.raw(0, 0), stored = expect_stored.raw(0, 0);
          bool pass;
          if (fmt == DepthFormat::d32f) pass = gl_passes(f, std::bit_cast<float>(frag), std::bit_cast<float>(stored));
          else pass = gl_passes(f, frag, stored);
          const std::string what = std::string(to_string(fmt)) + " path " + std::to_string(int(path)) + " func " +
                                   std::to_string(int(f)) + " frag " + std::to_string(c.frag) + " stored " +
                                   std::to_string(c.stored);
          for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
              ASSERT_EQ(d.raw(x, y), pass ? frag : stored) << what << " at " << x << "," << y;
              if (path != depth_only) {
                ASSERT_EQ(color.read(x, y).r, pass ? 1.0f : 0.0f) << what << " at " << x << "," << y;
              }
            }
        }
      }
}
