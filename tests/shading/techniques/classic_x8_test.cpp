// The eight-lane read of a classic map (classic_visibility_x8, the filters of shadow_filters_x8.h) equals the
// scalar classic_visibility point by point, bit for bit: every filter with single-compare and PCF taps, d16,
// d24 and d32f maps with border and edge wrap, directional and spot readers (points behind the light and off
// the map included), each bias kind, batches of one to eight points, shadowlab's and the tutorial's Poisson
// arithmetic.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/target.h"
#include "shading/techniques/classic.h"

namespace {

namespace tech = shading::tech;

// A map of random depths with some smooth areas, so early bailing both bails and does not.
raster::DepthTarget random_map(raster::DepthFormat f, int size, std::mt19937& rng) {
  raster::DepthTarget t(size, size, f);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float z = (x / 8 + y / 8) % 3 == 0 ? u(rng) : 0.2f + 0.6f * float((x / 16 + y / 16) % 2);
      if (f == raster::DepthFormat::d16) t.row<uint16_t>(y)[x] = uint16_t(z * 65535.0f);
      else if (f == raster::DepthFormat::d24) t.row<uint32_t>(y)[x] = uint32_t(z * 16777215.0f);
      else t.row<float>(y)[x] = z;
    }
  return t;
}

// Random points and the reader's matrix: directional st = (x, y), ref = z; spot (perspective) divides by w = z.
std::vector<tech::ShadowQuery> random_points(bool spot, std::mt19937& rng, size_t n) {
  std::uniform_real_distribution<float> u(-0.15f, 1.15f), z(0.0f, 1.0f), w(-0.3f, 2.0f), nr(-1.0f, 1.0f),
      px(0.0f, 1920.0f);
  std::vector<tech::ShadowQuery> q(n);
  for (auto& p : q) {
    glm::vec3 nrm(nr(rng), nr(rng), nr(rng));
    if (glm::dot(nrm, nrm) < 1e-4f) nrm = glm::vec3(0.0f, 0.0f, 1.0f);
    if (spot) {
      const float ww = w(rng);
      p.p = glm::vec3(u(rng) * ww, u(rng) * ww, ww);
    } else {
      p.p = glm::vec3(u(rng), u(rng), z(rng));
    }
    p.n = glm::normalize(nrm);
    p.frag = glm::vec2(std::floor(px(rng)) + 0.5f, std::floor(px(rng)) + 0.5f);
  }
  return q;
}

tech::ClassicReader reader(const shading::Texture2D& tex, shading::Wrap wrap, bool spot, tech::BiasMode bias) {
  tech::ClassicReader r;
  r.maps = tech::map_lookups(tex, wrap);
  r.bias.mode = bias;
  if (spot) {
    r.kind = tech::LightKind::spot;
    r.perspective = true;
    r.position = glm::vec3(0.5f, 0.5f, -1.0f);
    r.direction = glm::vec3(0.0f, 0.0f, 1.0f);
    // (x, y, z, 1) → (x, y, 0.9 z + 0.05, z)
    r.shadow = glm::mat4(1.0f);
    r.shadow[2] = glm::vec4(0.0f, 0.0f, 0.9f, 1.0f);
    r.shadow[3] = glm::vec4(0.0f, 0.0f, 0.05f, 0.0f);
  } else {
    r.direction = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
  }
  return r;
}

}  // namespace

TEST(ClassicX8, EqualsScalarClassicVisibilityPerPoint) {
  std::mt19937 rng(11);
  const tech::FilterKind kinds[] = {tech::FilterKind::hard,       tech::FilterKind::pcf,
                                    tech::FilterKind::poisson,    tech::FilterKind::stratified,
                                    tech::FilterKind::rotated,    tech::FilterKind::early_bail};
  size_t checked = 0, zero = 0, between = 0;
  for (raster::DepthFormat f : {raster::DepthFormat::d16, raster::DepthFormat::d24, raster::DepthFormat::d32f}) {
    const raster::DepthTarget map = random_map(f, 97, rng);
    const shading::Texture2D tex = shading::Texture2D::view(map);
    for (shading::Wrap wrap : {shading::Wrap::clamp_to_border, shading::Wrap::clamp_to_edge})
      for (bool spot : {false, true})
        for (tech::BiasMode bias : {tech::BiasMode::none, tech::BiasMode::slope, tech::BiasMode::normal})
          for (tech::FilterKind kind : kinds)
            for (bool pcf_taps : {false, true})
              for (int taps : {4, 16})
                for (bool tutorial : {false, true}) {
                if (tutorial && (kind == tech::FilterKind::hard || kind == tech::FilterKind::pcf ||
                                 kind == tech::FilterKind::early_bail))
                  continue;  // the tutorial variant is one of the Poisson filters only
                tech::ClassicReader r = reader(tex, wrap, spot, bias);
                r.filter.tutorial = tutorial;
                r.filter_kind = kind;
                r.filter.pcf_taps = pcf_taps;
                r.filter.taps = taps;
                r.filter.spread = 3.0f / 97.0f;
                r.filter.stratify_world = taps == 16;
                const std::vector<tech::ShadowQuery> pts = random_points(spot, rng, 64);
                for (size_t k = 0, size = 1; k < pts.size(); k += size, size = size % 8 + 1) {
                  const size_t m = std::min(size, pts.size() - k);
                  std::span<const tech::ShadowQuery> batch(pts.data() + k, m);
                  float wide[8], quad[8];
                  tech::classic_visibility_x8(r, batch, std::span(wide, m));
                  tech::classic_visibility(r, batch, std::span(quad, m));
                  for (size_t i = 0; i < m; ++i) {
                    ASSERT_EQ(std::bit_cast<uint32_t>(wide[i]), std::bit_cast<uint32_t>(quad[i]))
                        << "format " << int(f) << " wrap " << int(wrap) << " spot " << spot << " bias "
                        << int(bias) << " filter " << int(kind) << " pcf " << pcf_taps << " taps " << taps
                        << " tutorial " << tutorial
                        << " point " << k + i << " of a batch of " << m;
                    ++checked;
                    zero += quad[i] == 0.0f;
                    between += quad[i] > 0.0f && quad[i] < 1.0f;
                  }
                }
              }
  }
  // The cases are not degenerate: shadowed, lit and partly lit points all occur.
  EXPECT_GT(zero, checked / 20);
  EXPECT_GT(between, checked / 20);
}
