// ShadowLookup2D: the per-draw fast path for the common shadow case gives bit-identical results to the generic
// lookups, for every format and wrap it covers, inside, at and beyond the edges; other samplers fall back.
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "raster/target.h"
#include "shading/shadow_lookup.h"

namespace {

using shading::CompareFunc;
using shading::Sampler;
using shading::ShadowLookup2D;
using shading::Texture2D;
using shading::Wrap;

// The scalar twin of the SIMD kernels (always compiled, used by SHADOWLAB_SIMD=scalar builds).
float scalar_twin(const Texture2D& t, bool border, glm::vec3 p) {
  const auto& L = t.level(0);
  const float bd = 0.75f;
  switch (t.format()) {
    case shading::TexelFormat::d16:
      return border ? shading::detail::pcf_lequal_scalar<shading::TexelFormat::d16, true>(L, p, bd)
                    : shading::detail::pcf_lequal_scalar<shading::TexelFormat::d16, false>(L, p, bd);
    case shading::TexelFormat::d24:
      return border ? shading::detail::pcf_lequal_scalar<shading::TexelFormat::d24, true>(L, p, bd)
                    : shading::detail::pcf_lequal_scalar<shading::TexelFormat::d24, false>(L, p, bd);
    default:
      return border ? shading::detail::pcf_lequal_scalar<shading::TexelFormat::d32f, true>(L, p, bd)
                    : shading::detail::pcf_lequal_scalar<shading::TexelFormat::d32f, false>(L, p, bd);
  }
}

TEST(ShadowLookup2D, FastPathMatchesGenericBitForBit) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f), coord(-0.3f, 1.3f), ref(-0.1f, 1.1f);
  for (raster::DepthFormat f : {raster::DepthFormat::d16, raster::DepthFormat::d24, raster::DepthFormat::d32f}) {
    raster::DepthTarget target(37, 23, f);  // odd sizes; storage padded to the tile size
    for (int y = 0; y < 23; ++y)
      for (int x = 0; x < 37; ++x) {
        const float z = depth(rng);
        if (f == raster::DepthFormat::d16) target.row<uint16_t>(y)[x] = uint16_t(z * 65535.0f);
        if (f == raster::DepthFormat::d24) target.row<uint32_t>(y)[x] = uint32_t(z * 16777215.0f);
        if (f == raster::DepthFormat::d32f) target.row<float>(y)[x] = z;
      }
    const Texture2D tex = Texture2D::view(target);
    for (Wrap w : {Wrap::clamp_to_edge, Wrap::clamp_to_border}) {
      const Sampler s = Sampler::pcf(CompareFunc::lequal, w, 0.75f);
      const ShadowLookup2D lookup(tex, s);
      ASSERT_TRUE(lookup.fast());
      std::vector<glm::vec3> pts;
      for (int k = 0; k < 20000; ++k) pts.emplace_back(coord(rng), coord(rng), ref(rng));
      // Exact edges and texel centres too.
      for (float e : {0.0f, 1.0f, 0.5f / 37.0f, 36.5f / 37.0f}) pts.emplace_back(e, e, 0.5f);
      // Far outside, non-finite, and references beyond [0, 1] (clamped for d16 and d24 only).
      const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
      for (glm::vec3 q : {glm::vec3(1e9f, -1e9f, 0.5f), glm::vec3(inf, 0.5f, 0.5f), glm::vec3(nan, nan, 0.5f),
                          glm::vec3(0.5f, 0.5f, nan), glm::vec3(0.3f, 0.7f, 1.5f), glm::vec3(0.3f, 0.7f, -0.5f)})
        pts.push_back(q);
      std::vector<float> bulk(pts.size());
      lookup(pts, bulk);
      for (size_t k = 0; k < pts.size(); ++k) {
        const float generic = shading::texture_at(tex, s, pts[k], 0.0f);  // never the fast kernel
        ASSERT_EQ(std::bit_cast<uint32_t>(shading::texture(tex, s, pts[k])), std::bit_cast<uint32_t>(generic));
        ASSERT_EQ(std::bit_cast<uint32_t>(lookup(pts[k])), std::bit_cast<uint32_t>(generic))
            << raster::to_string(f) << " " << shading::to_string(w) << " at " << pts[k].x << ", " << pts[k].y;
        ASSERT_EQ(std::bit_cast<uint32_t>(bulk[k]), std::bit_cast<uint32_t>(generic)) << k;
        ASSERT_EQ(std::bit_cast<uint32_t>(scalar_twin(tex, w == Wrap::clamp_to_border, pts[k])),
                  std::bit_cast<uint32_t>(generic));
      }
    }
  }
}

TEST(ShadowLookup2D, OtherSamplersTakeTheGenericPath) {
  const Texture2D d32 =
      Texture2D::from_floats(2, 2, shading::TexelFormat::d32f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
  EXPECT_EQ(ShadowLookup2D(d32, Sampler::pcf(CompareFunc::greater)).path(), ShadowLookup2D::Path::generic);
  EXPECT_EQ(ShadowLookup2D(d32, Sampler::pcf(CompareFunc::lequal, Wrap::repeat)).path(), ShadowLookup2D::Path::generic);
  EXPECT_EQ(ShadowLookup2D(d32, Sampler::plain(shading::Filter::linear)).path(), ShadowLookup2D::Path::generic);
  EXPECT_EQ(ShadowLookup2D(d32, Sampler::pcf()).path(), ShadowLookup2D::Path::d32f_edge);
  const Texture2D r32 =
      Texture2D::from_floats(2, 2, shading::TexelFormat::r32f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
  EXPECT_EQ(ShadowLookup2D(r32, Sampler::pcf()).path(), ShadowLookup2D::Path::generic);
  // The generic path still answers, and as texture() does.
  const ShadowLookup2D g(d32, Sampler::pcf(CompareFunc::greater));
  EXPECT_EQ(g(glm::vec3(0.625f, 0.375f, 0.4f)),
            shading::texture(d32, Sampler::pcf(CompareFunc::greater), glm::vec3(0.625f, 0.375f, 0.4f)));
  EXPECT_EQ(g(glm::vec3(0.625f, 0.375f, 0.4f)), 0.1875f);  // only texel (0, 0) = 0.2 < 0.4, weight 0.1875
}

TEST(ShadowLookup2D, VisitHandsOutTheSpecialisedKernel) {
  const Texture2D d32 =
      Texture2D::from_floats(2, 2, shading::TexelFormat::d32f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
  const glm::vec3 p(0.625f, 0.375f, 0.5f);
  const bool fast = ShadowLookup2D(d32, Sampler::pcf()).visit([&](auto kernel) {
    EXPECT_EQ(kernel(p), 0.25f);
    return std::is_same_v<decltype(kernel), shading::PcfKernel<shading::TexelFormat::d32f, false>>;
  });
  EXPECT_TRUE(fast);
  const bool generic = ShadowLookup2D(d32, Sampler::pcf(CompareFunc::gequal)).visit([&](auto kernel) {
    EXPECT_EQ(kernel(p), 0.75f);  // 0.5 >= 0.2 and 0.4 (the bottom row): weights 0.1875 + 0.5625
    return std::is_same_v<decltype(kernel), shading::GenericShadowKernel>;
  });
  EXPECT_TRUE(generic);
}

TEST(ShadowLookup2D, ProjAndQuadForms) {
  const Texture2D d32 =
      Texture2D::from_floats(2, 2, shading::TexelFormat::d32f, 1, std::vector<float>{0.2f, 0.4f, 0.6f, 0.8f});
  const ShadowLookup2D lookup(d32, Sampler::pcf());
  // (1.25, 0.75, 1.0, 2) → (0.625, 0.375, 0.5): results 0, 0, 1, 1 with weights 0.1875 … → 0.25.
  EXPECT_EQ(lookup.proj(glm::vec4(1.25f, 0.75f, 1.0f, 2.0f)), 0.25f);
  EXPECT_EQ(lookup.proj(glm::vec4(1.25f, 0.75f, 1.0f, 0.0f)), 0.0f);
  const shading::Quad<float> q = lookup({glm::vec3(0.625f, 0.375f, 0.5f), glm::vec3(0.625f, 0.375f, 0.1f),
                                         glm::vec3(0.625f, 0.375f, 0.9f), glm::vec3(0.625f, 0.375f, 0.4f)});
  EXPECT_EQ(q[0], 0.25f);
  EXPECT_EQ(q[1], 1.0f);
  EXPECT_EQ(q[2], 0.0f);
  EXPECT_EQ(q[3], 0.8125f);
}

}  // namespace
