// ShadowLookup2D: the per-draw fast path for the common shadow case gives bit-identical results to the generic
// lookups, for every format and wrap it covers, inside, at and beyond the edges; other samplers fall back. So does
// GenericShadowKernel's shorter path for NEAREST compare samplers (detail::nearest_compare).
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "raster/simd/vec.h"
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

// NEAREST shadow samplers: GenericShadowKernel's short path (one texel read and compared) equals the general
// lookup bit for bit, in its one-lane and eight-lane forms: the three depth formats, views of padded targets
// and packed storage, sizes down to one texel, clamp_to_edge and clamp_to_border (border depths inside and
// outside [0, 1], which d16 and d24 clamp), all eight compare functions, references outside [0, 1], coordinates
// on every texel boundary and centre, around and beyond the map, huge and non-finite ones.
TEST(GenericShadowKernel, NearestPathEqualsTheGeneralLookup) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f), coord(-0.3f, 1.3f), ref(-0.2f, 1.2f);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  int checked = 0;
  for (auto [w, h] : {std::pair{37, 23}, {1, 1}, {2, 3}, {64, 5}}) {
    for (auto f : {shading::TexelFormat::d16, shading::TexelFormat::d24, shading::TexelFormat::d32f}) {
      std::vector<float> z(size_t(w) * h);
      for (float& v : z) v = depth(rng);
      const raster::DepthFormat df = f == shading::TexelFormat::d16   ? raster::DepthFormat::d16
                               : f == shading::TexelFormat::d24 ? raster::DepthFormat::d24
                                                                 : raster::DepthFormat::d32f;
      raster::DepthTarget target(w, h, df);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const float v = z[size_t(y) * w + x];
          if (df == raster::DepthFormat::d16) target.row<uint16_t>(y)[x] = uint16_t(v * 65535.0f);
          if (df == raster::DepthFormat::d24) target.row<uint32_t>(y)[x] = uint32_t(v * 16777215.0f) | 0xAB000000u;
          if (df == raster::DepthFormat::d32f) target.row<float>(y)[x] = v;
        }
      const Texture2D textures[] = {Texture2D::from_floats(w, h, f, 1, z), Texture2D::view(target)};
      std::vector<glm::vec3> pts;
      for (int k = 0; k < 400; ++k) pts.emplace_back(coord(rng), coord(rng), ref(rng));
      for (int i = -1; i <= w + 1; ++i)
        for (int j = -1; j <= h + 1; ++j)
          for (float d : {0.0f, 0.5f})
            pts.emplace_back((float(i) + d) / float(w), (float(j) + d) / float(h), ref(rng));
      for (glm::vec3 q : {glm::vec3(1e9f, -1e9f, 0.5f), glm::vec3(-inf, inf, 0.5f), glm::vec3(nan, 0.5f, 0.5f),
                          glm::vec3(0.5f, nan, 0.5f), glm::vec3(0.5f, 0.5f, nan), glm::vec3(0.5f, 0.5f, inf),
                          glm::vec3(-1e-7f, 1.0f + 1e-7f, 0.5f), glm::vec3(1.0f, 1.0f, 0.5f)})
        pts.push_back(q);
      while (pts.size() % 8) pts.emplace_back(0.5f, 0.5f, 0.5f);
      for (const Texture2D& tex : textures)
        for (Wrap wrap : {Wrap::clamp_to_edge, Wrap::clamp_to_border})
          for (int func = 0; func < 8; ++func)
            for (float border : {0.4f, -0.5f, 1.5f}) {
              Sampler s = Sampler::pcf(CompareFunc(func), wrap, border);
              s.mag_filter = s.min_filter = shading::Filter::nearest;
              const shading::GenericShadowKernel kernel(&tex, s);
              ASSERT_TRUE(kernel.nearest_fast());
              for (size_t k = 0; k < pts.size(); k += 8) {
                alignas(32) float ps[8], pt[8], pr[8], out[8];
                for (int l = 0; l < 8; ++l) ps[l] = pts[k + l].x, pt[l] = pts[k + l].y, pr[l] = pts[k + l].z;
                kernel(raster::simd::VecF32::load(ps), raster::simd::VecF32::load(pt), raster::simd::VecF32::load(pr))
                    .store(out);
                for (int l = 0; l < 8; ++l) {
                  const glm::vec3 p = pts[k + l];
                  const float general = shading::texture_at(tex, s, p, 0.0f);
                  ASSERT_EQ(std::bit_cast<uint32_t>(kernel(p)), std::bit_cast<uint32_t>(general))
                      << int(f) << " " << w << "x" << h << " wrap " << int(wrap) << " func " << func << " border "
                      << border << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
                  ASSERT_EQ(std::bit_cast<uint32_t>(out[l]), std::bit_cast<uint32_t>(general)) << "eight lanes";
                  ++checked;
                }
              }
            }
    }
  }
  EXPECT_GT(checked, 100000);
}

// Samplers the NEAREST path does not cover keep the general lookup.
TEST(GenericShadowKernel, OtherSamplersTakeTheGeneralLookup) {
  const std::vector<float> z{0.2f, 0.4f, 0.6f, 0.8f};
  const Texture2D d32 = Texture2D::from_floats(2, 2, shading::TexelFormat::d32f, 1, z);
  const Texture2D mipped = Texture2D::from_floats(2, 2, shading::TexelFormat::d32f, 1, z, true);
  const Texture2D colour = Texture2D::from_floats(2, 2, shading::TexelFormat::r32f, 1, z);
  Sampler nearest = Sampler::pcf();
  nearest.mag_filter = nearest.min_filter = shading::Filter::nearest;
  EXPECT_TRUE(shading::GenericShadowKernel(&d32, nearest).nearest_fast());
  EXPECT_FALSE(shading::GenericShadowKernel(&colour, nearest).nearest_fast());
  auto with = [&](auto change) {
    Sampler s = nearest;
    change(s);
    return s;
  };
  for (const Sampler& s : {Sampler::pcf(), with([](Sampler& x) { x.min_filter = shading::Filter::linear; }),
                           with([](Sampler& x) { x.compare_mode = shading::CompareMode::none; }),
                           with([](Sampler& x) { x.wrap_s = x.wrap_t = Wrap::repeat; }),
                           with([](Sampler& x) { x.wrap_s = x.wrap_t = Wrap::clamp; }),
                           with([](Sampler& x) { x.wrap_t = Wrap::clamp_to_border; })})
    EXPECT_FALSE(shading::GenericShadowKernel(&d32, s).nearest_fast());
  const Sampler mips = with([](Sampler& x) { x.mip_filter = shading::MipFilter::nearest; });
  EXPECT_FALSE(shading::GenericShadowKernel(&mipped, mips).nearest_fast());
  EXPECT_TRUE(shading::GenericShadowKernel(&d32, mips).nearest_fast());  // one level: λ cannot matter
}

}  // namespace
