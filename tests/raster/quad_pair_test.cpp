// The wide fragment stage (fragment_pair, two quads in SIMD lanes) against the quad path: the same shader drawn
// through both gives bit-identical colour and depth, over random perspective triangles with partial coverage
// and clipping, with early depth testing, discard and depth writes, every depth format, the RGBA8 fast colour
// write and the per-pixel fallbacks (sRGB, RGBA32F, multiply blend), at 0, 1, 2, 7 and 16 threads. Also the pair
// derivatives against the quad ones.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "raster/quad_path_only.h"
#include "raster/renderer.h"

using namespace raster;
using simd::VecF32;

namespace {

struct PairVertex {
  glm::vec4 pos;
  glm::vec3 c;
  glm::vec2 uv;
};

// Colour from varyings, gl_FragCoord and fine and coarse derivatives; Mode 1 discards, Mode 2 writes depth.
// fragment() and fragment_pair() spell out the same operations in the same order.
template <int Mode>
struct PairShader {
  using Vertex = PairVertex;
  struct Varyings {
    glm::vec3 c;
    glm::vec2 uv;
  };
  static constexpr bool kDiscards = Mode == 1;
  static constexpr bool kWritesDepth = Mode == 2;

  glm::vec4 vertex(const Vertex& v, Varyings& o) const {
    o.c = v.c;
    o.uv = v.uv;
    return v.pos;
  }

  void fragment(const QuadIn<Varyings>& q, QuadOut& out) const {
    std::array<float, 4> u, v;
    for (int l = 0; l < 4; ++l) u[l] = q.in[l].uv.x, v[l] = q.in[l].uv.y;
    const auto ux = dfdx_fine(u), vy = dfdy_coarse(v), uy = dfdy_fine(u), vx = dfdx_coarse(v);
    for (int l = 0; l < 4; ++l) {
      const glm::vec4& f = q.frag_coord[l];
      const float r = q.in[l].c.x;
      const float g = q.in[l].c.y * f.w;
      const float b = (ux[l] + vy[l]) * 40.0f + f.z;
      const float a = (uy[l] - vx[l]) * 40.0f + f.x * 0.01f + f.y * 0.02f + (q.front_facing ? 0.0f : 0.5f);
      out.color[l] = glm::vec4(r, g, b, a);
      if constexpr (Mode == 1)
        if (q.in[l].c.z < 0.3f) out.discard = uint8_t(out.discard | (1u << l));
      if constexpr (Mode == 2) out.depth[l] = q.in[l].c.z * 1.4f - 0.2f;
    }
  }

  void fragment_pair(const QuadPairIn<Varyings>& q, QuadPairOut& out) const {
    const VecF32 u = q.in[3], v = q.in[4];  // uv follows the three floats of c
    const VecF32 ux = dfdx_fine(u), vy = dfdy_coarse(v), uy = dfdy_fine(u), vx = dfdx_coarse(v);
    const VecF32 r = q.in[0];
    const VecF32 g = q.in[1] * q.frag_w;
    const VecF32 b = (ux + vy) * VecF32::splat(40.0f) + q.frag_z;
    const VecF32 a = (uy - vx) * VecF32::splat(40.0f) + q.frag_x * VecF32::splat(0.01f) +
                     q.frag_y * VecF32::splat(0.02f) + VecF32::splat(q.front_facing ? 0.0f : 0.5f);
    out.color = {r, g, b, a};
    if constexpr (Mode == 1) out.discard = uint8_t(simd::cmp_lt(q.in[2], VecF32::splat(0.3f)).bits());
    if constexpr (Mode == 2) out.depth = q.in[2] * VecF32::splat(1.4f) - VecF32::splat(0.2f);
  }
};

// The same shader with only its quad form visible: the pipeline takes the quad path.
template <class S>
using QuadOnly = QuadPathOnly<S>;

static_assert(HasPairFragmentStage<PairShader<0>>);
static_assert(!HasPairFragmentStage<QuadOnly<PairShader<0>>>);

// Random triangles over a 97×61 target (partial tiles and blocks): small and large, some reaching behind the
// eye or beyond the sides (clipped), perspective w, both windings.
std::vector<PairVertex> random_scene(uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-1.3f, 1.3f), w(0.4f, 2.5f), z(-1.2f, 1.2f), unit(0.0f, 1.0f),
      small(-0.15f, 0.15f);
  std::vector<PairVertex> v;
  for (int t = 0; t < count; ++t) {
    const bool tiny = t % 3 == 0;
    const glm::vec2 centre(pos(rng), pos(rng));
    for (int k = 0; k < 3; ++k) {
      const glm::vec2 p = tiny ? centre + glm::vec2(small(rng), small(rng)) : glm::vec2(pos(rng), pos(rng));
      const float cw = (t % 17 == 0 && k == 0) ? -0.5f : w(rng);
      v.push_back({glm::vec4(p.x * cw, p.y * cw, z(rng) * cw, cw), glm::vec3(unit(rng), unit(rng), unit(rng)),
                   glm::vec2(unit(rng) * 4.0f, unit(rng) * 4.0f)});
    }
  }
  return v;
}

struct Output {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
};

template <class Shader>
Output render(int threads, const Shader& shader, const std::vector<PairVertex>& scene, DepthFormat df,
              const DrawState& state, ColorFormat cf, bool srgb) {
  const int W = 97, H = 61;
  Renderer r(threads);
  DepthTarget depth(W, H, df);
  ColorTarget color(W, H, cf, srgb);
  color.clear(glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
  r.draw(RenderTargets{&depth, &color}, state, shader, std::span<const PairVertex>(scene));
  Output o;
  for (int y = 0; y < H; ++y) {
    const size_t bytes = size_t(W) * (cf == ColorFormat::rgba8 ? 4 : 16);
    const uint8_t* p = cf == ColorFormat::rgba8 ? color.row8(y) : reinterpret_cast<const uint8_t*>(color.row32f(y));
    o.color.insert(o.color.end(), p, p + bytes);
    for (int x = 0; x < W; ++x) o.depth.push_back(depth.raw(x, y));
  }
  return o;
}

template <int Mode>
void expect_paths_match(DepthFormat df, DepthFunc func, ColorFormat cf, bool srgb, BlendMode blend) {
  const std::vector<PairVertex> scene = random_scene(1000u + uint32_t(Mode) * 7u + uint32_t(df), 120);
  DrawState state;
  state.depth_func = func;
  state.blend = blend;
  const PairShader<Mode> pair{};
  const Output quad = render(0, QuadOnly<PairShader<Mode>>{pair}, scene, df, state, cf, srgb);
  for (int threads : {0, 1, 2, 7, 16}) {
    const Output wide = render(threads, pair, scene, df, state, cf, srgb);
    const std::string what = "mode " + std::to_string(Mode) + " " + std::string(to_string(df)) + " func " +
                             std::to_string(int(func)) + " threads " + std::to_string(threads);
    ASSERT_EQ(wide.depth, quad.depth) << what;
    ASSERT_EQ(wide.color, quad.color) << what;
  }
}

}  // namespace

TEST(QuadPair, EarlyDepthPathMatchesQuadsBitForBit) {
  for (DepthFormat df : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    for (DepthFunc func : {DepthFunc::less, DepthFunc::gequal, DepthFunc::always})
      expect_paths_match<0>(df, func, ColorFormat::rgba8, false, BlendMode::replace);
}

TEST(QuadPair, DiscardMatchesQuadsBitForBit) {
  for (DepthFormat df : {DepthFormat::d16, DepthFormat::d32f})
    expect_paths_match<1>(df, DepthFunc::lequal, ColorFormat::rgba8, false, BlendMode::replace);
}

TEST(QuadPair, DepthWriteMatchesQuadsBitForBit) {
  for (DepthFormat df : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f})
    expect_paths_match<2>(df, DepthFunc::less, ColorFormat::rgba8, false, BlendMode::replace);
}

TEST(QuadPair, PerPixelColourFallbacksMatchQuads) {
  expect_paths_match<0>(DepthFormat::d32f, DepthFunc::less, ColorFormat::rgba8, true, BlendMode::replace);
  expect_paths_match<0>(DepthFormat::d32f, DepthFunc::less, ColorFormat::rgba32f, false, BlendMode::replace);
  expect_paths_match<1>(DepthFormat::d24, DepthFunc::less, ColorFormat::rgba8, false, BlendMode::multiply);
}

// Without a depth buffer and with depth testing off, as the PCF benchmark draws.
TEST(QuadPair, ColourOnlyMatchesQuads) {
  const std::vector<PairVertex> scene = random_scene(99, 60);
  DrawState state;
  state.depth_test = false;
  for (int threads : {0, 2}) {
    Renderer r(threads);
    ColorTarget a(97, 61, ColorFormat::rgba8), b(97, 61, ColorFormat::rgba8);
    r.draw(RenderTargets{nullptr, &a}, state, PairShader<0>{}, std::span<const PairVertex>(scene));
    r.draw(RenderTargets{nullptr, &b}, state, QuadOnly<PairShader<0>>{}, std::span<const PairVertex>(scene));
    for (int y = 0; y < 61; ++y) ASSERT_EQ(std::memcmp(a.row8(y), b.row8(y), 97 * 4), 0) << "row " << y;
  }
}

// The pair derivatives are the quad ones, lane by lane: quad 0 is lanes {0, 1, 4, 5}, quad 1 lanes {2, 3, 6, 7}.
TEST(QuadPair, DerivativesMatchTheQuadFunctions) {
  alignas(32) const float v[8] = {1.0f, 2.5f, -4.0f, 8.25f, 16.0f, 0.125f, 3.0f, -7.5f};
  const int quad_lanes[2][4] = {{0, 1, 4, 5}, {2, 3, 6, 7}};
  auto check = [&](VecF32 got, auto quad_fn) {
    alignas(32) float g[8];
    got.store(g);
    for (const auto& ql : quad_lanes) {
      const std::array<float, 4> q = {v[ql[0]], v[ql[1]], v[ql[2]], v[ql[3]]};
      const std::array<float, 4> want = quad_fn(q);
      for (int l = 0; l < 4; ++l) EXPECT_EQ(g[ql[l]], want[size_t(l)]) << "lane " << ql[l];
    }
  };
  const VecF32 x = VecF32::load(v);
  check(dfdx_fine(x), [](const std::array<float, 4>& q) { return dfdx_fine(q); });
  check(dfdy_fine(x), [](const std::array<float, 4>& q) { return dfdy_fine(q); });
  check(dfdx_coarse(x), [](const std::array<float, 4>& q) { return dfdx_coarse(q); });
  check(dfdy_coarse(x), [](const std::array<float, 4>& q) { return dfdy_coarse(q); });
}

TEST(QuadPair, VaryingIndexFollowsDeclarationOrder) {
  using V = PairShader<0>::Varyings;
  EXPECT_EQ(varying_index(&V::c), 0);
  EXPECT_EQ(varying_index(&V::uv), 3);
}
