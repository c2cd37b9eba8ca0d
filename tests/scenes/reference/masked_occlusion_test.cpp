// The reference's alpha test: a masked caster blocks a ray only where its material's alpha passes, the test
// the depth passes run (shading/surface_texture.h), through Embree's occlusion filter.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "scenes/reference/occlusion_scene.h"
#include "shading/surface_texture.h"

namespace {

// A unit square at z = 0, x and y in [0, 1], (s, t) = (x, y), split into two triangles; its texture is 2 × 1
// texels: alpha 1 on the left half (s < 0.5), 0 on the right.
struct MaskedSquare {
  shading::Texture2D texture =
      shading::Texture2D::from_floats(2, 1, shading::TexelFormat::rgba8, 4, std::vector<float>{1, 1, 1, 1, 1, 1, 1, 0});
  std::vector<shading::SurfaceTexture> surfaces;
  scenes::CoverageSoup soup;
  MaskedSquare(const MaskedSquare&) = delete;  // surfaces point at `texture`
  MaskedSquare(bool masked, float cutoff) {
    shading::SurfaceTexture s;
    s.texture = &texture;
    s.sampler = shading::Sampler::plain(shading::Filter::nearest, shading::Wrap::clamp_to_edge);
    s.masked = masked;
    s.cutoff = cutoff;
    surfaces = {s};
    scenes::MaskedSoup m;
    m.material = 0;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    soup.masked = {m};
  }
};

bool blocked(const reference::OcclusionScene& occ, float x, float y) {
  return occ.occluded({x, y, 1.0f}, {0.0f, 0.0f, -1.0f}, 2.0f);
}

}  // namespace

TEST(MaskedOcclusion, RaysPassWhereAlphaIsBelowTheCutoff) {
  const MaskedSquare sq(true, 0.5f);
  const reference::OcclusionScene occ(sq.soup, sq.surfaces);
  EXPECT_EQ(occ.triangles(), 2u);
  for (float y : {0.1f, 0.5f, 0.9f}) {
    for (float x : {0.05f, 0.2f, 0.45f}) EXPECT_TRUE(blocked(occ, x, y)) << x << ", " << y;   // alpha 1
    for (float x : {0.55f, 0.8f, 0.95f}) EXPECT_FALSE(blocked(occ, x, y)) << x << ", " << y;  // alpha 0
  }
  EXPECT_FALSE(blocked(occ, 1.5f, 0.5f));  // beside the square
}

TEST(MaskedOcclusion, UnmaskedOrZeroCutoffBlocksEverywhere) {
  for (const auto& [masked, cutoff] : {std::pair{false, 0.5f}, std::pair{true, 0.0f}}) {
    const MaskedSquare sq(masked, cutoff);
    const reference::OcclusionScene occ(sq.soup, sq.surfaces);
    for (float x : {0.2f, 0.8f}) EXPECT_TRUE(blocked(occ, x, 0.5f)) << x << (masked ? " masked" : "");
  }
}
