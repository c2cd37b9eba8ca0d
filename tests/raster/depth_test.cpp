// Depth: interpolation from the window-space plane, quantisation per format, the eight depth functions,
// depth write mask, polygon offset (factor and units) as CONVENTIONS defines it.
#include <gtest/gtest.h>

#include <cmath>

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
