// Cube maps: GL's major-axis table for the six axes, edges and corners (ties resolved z over y over x), the
// neighbour texel seamless filtering reads across an edge, the corner rule, face views that render what the
// table reads, and LOD from direction derivatives.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/gtc/constants.hpp>

#include "shading/lookup_cube.h"

namespace {

using shading::CubeCoord;
using shading::Filter;
using shading::Sampler;
using shading::TexelFormat;
using shading::Texture2D;
using shading::TextureCube;

TEST(CubeFace, SixAxesByTheMajorAxisTable) {
  struct Case {
    glm::vec3 dir;
    int face;
    float s, t;
  };
  // s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 with (sc, tc) per face from GL's table, worked by hand.
  const Case cases[] = {
      {{1.0f, 0.5f, -0.25f}, 0, 0.625f, 0.25f},   // +X: sc = −rz = 0.25, tc = −ry = −0.5
      {{-1.0f, 0.5f, -0.25f}, 1, 0.375f, 0.25f},  // −X: sc = +rz = −0.25, tc = −ry = −0.5
      {{0.5f, 1.0f, -0.25f}, 2, 0.75f, 0.375f},   // +Y: sc = +rx = 0.5, tc = +rz = −0.25
      {{0.5f, -1.0f, -0.25f}, 3, 0.75f, 0.625f},  // −Y: sc = +rx = 0.5, tc = −rz = 0.25
      {{0.5f, -0.25f, 1.0f}, 4, 0.75f, 0.625f},   // +Z: sc = +rx = 0.5, tc = −ry = 0.25
      {{0.5f, -0.25f, -1.0f}, 5, 0.25f, 0.625f},  // −Z: sc = −rx = −0.5, tc = −ry = 0.25
      {{2.0f, 1.0f, -0.5f}, 0, 0.625f, 0.25f},    // |ma| = 2: the same point of +X
      {{0.0f, 0.0f, 3.0f}, 4, 0.5f, 0.5f},        // axis: the face centre
  };
  for (const Case& c : cases) {
    const CubeCoord cc = shading::cube_coord(c.dir);
    EXPECT_EQ(cc.face, c.face) << c.dir.x << " " << c.dir.y << " " << c.dir.z;
    EXPECT_EQ(cc.s, c.s) << c.face;
    EXPECT_EQ(cc.t, c.t) << c.face;
  }
}

TEST(CubeFace, EdgesAndCornersPreferZThenY) {
  EXPECT_EQ(shading::cube_face_of({1, 1, 0}), 2);  // |x| = |y|: y
  EXPECT_EQ(shading::cube_face_of({1, -1, 0}), 3);
  EXPECT_EQ(shading::cube_face_of({-1, 1, 0}), 2);
  EXPECT_EQ(shading::cube_face_of({1, 0, 1}), 4);  // |x| = |z|: z
  EXPECT_EQ(shading::cube_face_of({-1, 0, -1}), 5);
  EXPECT_EQ(shading::cube_face_of({0, 1, -1}), 5);  // |y| = |z|: z
  EXPECT_EQ(shading::cube_face_of({1, 1, 1}), 4);   // corners: z
  EXPECT_EQ(shading::cube_face_of({-1, -1, -1}), 5);
  EXPECT_EQ(shading::cube_face_of({1, 1, -1}), 5);
  EXPECT_EQ(shading::cube_face_of({1, 1.0001f, 1}), 2);  // just off the corner: y
  EXPECT_EQ(shading::cube_face_of({1.0001f, 1, 1}), 0);
  // On the +Y face the edge shared with +X is s = 1.
  const CubeCoord c = shading::cube_coord({1, 1, 0});
  EXPECT_EQ(c.s, 1.0f);
  EXPECT_EQ(c.t, 0.5f);
  // The corner (1, 1, 1) on +Z: sc = rx = 1, tc = −ry = −1.
  const CubeCoord k = shading::cube_coord({1, 1, 1});
  EXPECT_EQ(k.s, 1.0f);
  EXPECT_EQ(k.t, 0.0f);
}

TEST(CubeFace, NeighbourTexelsAcrossEdges) {
  const int n = 4;
  // +X, s beyond 1 (toward −Z): on −Z, sc = −rx with rx = 1 → s = 0; tc = −ry on both faces → same row.
  for (int j = 0; j < n; ++j) {
    const auto t = shading::cube_neighbor(0, n, j, n);
    EXPECT_EQ(t.face, 5);
    EXPECT_EQ(t.i, 0);
    EXPECT_EQ(t.j, j);
  }
  // +X, s below 0 (toward +Z): on +Z, sc = rx = 1 → s = 1, the last column; same row.
  const auto a = shading::cube_neighbor(0, -1, 2, n);
  EXPECT_EQ(a.face, 4);
  EXPECT_EQ(a.i, n - 1);
  EXPECT_EQ(a.j, 2);
  // +X, t beyond 1 (toward −Y): on −Y, sc = rx = 1 → last column; tc = −rz, and +X's s = −rz → row i.
  for (int i = 0; i < n; ++i) {
    const auto t = shading::cube_neighbor(0, i, n, n);
    EXPECT_EQ(t.face, 3);
    EXPECT_EQ(t.i, n - 1);
    EXPECT_EQ(t.j, i);
  }
  // +Y, t below 0 (toward −Z): on −Z, tc = −ry = −1 → t = 0; sc = −rx, and +Y's s = rx → column n − 1 − i.
  for (int i = 0; i < n; ++i) {
    const auto t = shading::cube_neighbor(2, i, -1, n);
    EXPECT_EQ(t.face, 5);
    EXPECT_EQ(t.i, n - 1 - i);
    EXPECT_EQ(t.j, 0);
  }
}

TEST(CubeFace, NeighbourAgreesWithLookingUpTheTexelCentreDirection) {
  // For every face and every texel just off each edge: the direction through that (virtual) texel centre,
  // looked up in floating point, lands in the texel cube_neighbor names.
  const int n = 8;
  for (int f = 0; f < 6; ++f) {
    const auto& ax = shading::kCubeFaceAxes[f];
    for (int k = 0; k < n; ++k) {
      const int off[4][2] = {{-1, k}, {n, k}, {k, -1}, {k, n}};
      for (const auto& o : off) {
        const float sc = (2.0f * float(o[0]) + 1.0f - float(n)) / float(n);
        const float tc = (2.0f * float(o[1]) + 1.0f - float(n)) / float(n);
        const glm::vec3 d = glm::vec3(ax.major) + sc * glm::vec3(ax.s_axis) + tc * glm::vec3(ax.t_axis);
        const CubeCoord c = shading::cube_coord(d);
        const auto t = shading::cube_neighbor(f, o[0], o[1], n);
        EXPECT_EQ(t.face, c.face);
        EXPECT_EQ(t.i, std::min(n - 1, int(c.s * float(n))));
        EXPECT_EQ(t.j, std::min(n - 1, int(c.t * float(n))));
      }
    }
  }
}

TEST(CubeFace, FaceViewsRenderWhatTheTableReads) {
  // A direction projected through a face's view and a 90° perspective lands at window (s, t) · size.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const glm::mat4 proj = glm::perspective(glm::half_pi<float>(), 1.0f, 0.1f, 10.0f);
  const glm::vec3 eye(0.3f, -1.0f, 2.0f);
  for (int k = 0; k < 2000; ++k) {
    const glm::vec3 d(u(rng), u(rng), u(rng));
    const CubeCoord c = shading::cube_coord(d);
    const glm::vec4 clip = proj * shading::cube_face_view(c.face, eye) * glm::vec4(eye + d, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    EXPECT_NEAR((clip.x / clip.w + 1.0f) * 0.5f, c.s, 1e-5f);
    EXPECT_NEAR((clip.y / clip.w + 1.0f) * 0.5f, c.t, 1e-5f);
  }
}

// A cube of 2 × 2 faces whose texels all hold their face's value.
TextureCube cube_of(TexelFormat format, const float (&value)[6]) {
  std::array<Texture2D, 6> faces;
  for (int f = 0; f < 6; ++f)
    faces[size_t(f)] = Texture2D::from_floats(2, 2, format, 1, std::vector<float>(4, value[f]));
  return TextureCube(faces);
}

TEST(CubeSampling, SeamlessLinearReadsTheAdjacentFace) {
  const TextureCube cube = cube_of(TexelFormat::r32f, {0, 1, 2, 3, 4, 5});
  Sampler s = Sampler::plain(Filter::linear);
  // (1, 0, −0.75) on +X: s = 0.875 → u = 1.25: taps 1 (on +X) and 2 (off the edge, on −Z) with weights
  // 0.75, 0.25; t = 0.5 keeps both rows on the same faces. 0.75·0 + 0.25·5 = 1.25.
  EXPECT_EQ(shading::texture(cube, s, glm::vec3(1.0f, 0.0f, -0.75f)).r, 1.25f);
  s.seamless_cube = false;  // per-face clamp_to_edge: only +X
  EXPECT_EQ(shading::texture(cube, s, glm::vec3(1.0f, 0.0f, -0.75f)).r, 0.0f);
}

TEST(CubeSampling, SeamlessCornerTapIsTheMeanOfTheOtherThree) {
  const TextureCube cube = cube_of(TexelFormat::r32f, {0, 1, 2, 3, 4, 5});
  const Sampler s = Sampler::plain(Filter::linear);
  // (1, −0.75, −0.75) on +X: s = t = 0.875, u = v = 1.25: taps (1,1) on +X = 0, (2,1) off s → −Z = 5,
  // (1,2) off t → −Y = 3, (2,2) off both: the corner, (0 + 5 + 3)/3. Weights a = b = 0.25.
  const float corner = (0.0f + 5.0f + 3.0f) / 3.0f;
  const float bottom = 0.0f + 0.25f * (5.0f - 0.0f), top = 3.0f + 0.25f * (corner - 3.0f);
  EXPECT_EQ(shading::texture(cube, s, glm::vec3(1.0f, -0.75f, -0.75f)).r, bottom + 0.25f * (top - bottom));
  // PCF: depths 0.1 on +X, 0.9 on −Z and −Y; reference 0.5 LEQUAL → 0, 1, 1 and a corner of 2/3.
  const TextureCube depth = cube_of(TexelFormat::d32f, {0.1f, 0.5f, 0.5f, 0.9f, 0.5f, 0.9f});
  const float c2 = 2.0f / 3.0f;
  const float b2 = 0.0f + 0.25f * 1.0f, t2 = 1.0f + 0.25f * (c2 - 1.0f);
  EXPECT_EQ(shading::texture(depth, Sampler::pcf(), glm::vec4(1.0f, -0.75f, -0.75f, 0.5f)), b2 + 0.25f * (t2 - b2));
}

TEST(CubeSampling, LodFromDirectionDerivatives) {
  TextureCube cube(8, TexelFormat::r32f, true);
  for (int f = 0; f < 6; ++f)
    for (int l = 0; l < cube.levels(); ++l)
      for (int j = 0; j < cube.size(l); ++j)
        for (int i = 0; i < cube.size(l); ++i) cube.face(f).set_texel(i, j, glm::vec4(float(l)), l);
  const Sampler s = Sampler::plain(Filter::linear, shading::Wrap::clamp_to_edge, shading::MipFilter::linear);
  // At (1, 0, 0) on +X, s = (−rz + 1)/2: a change of −0.5 in z per pixel moves s by 0.25 = 2 texels → λ = 1.
  EXPECT_EQ(shading::texture_grad(cube, s, glm::vec3(1, 0, 0), glm::vec3(0, 0, -0.5f), glm::vec3(0)).r, 1.0f);
  // Moving along the major axis changes nothing at the face centre (sc = tc = 0): λ = −∞, level 0.
  EXPECT_EQ(shading::texture_grad(cube, s, glm::vec3(1, 0, 0), glm::vec3(0.5f, 0, 0), glm::vec3(0)).r, 0.0f);
  // A quad spanning 4 texels per pixel in t (−y on +X): λ = 2.
  const shading::Quad<glm::vec3> q = {glm::vec3(1, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, -1, 0), glm::vec3(1, -1, 0)};
  EXPECT_EQ(shading::texture(cube, s, q)[0].r, 2.0f);
}

TEST(TextureCubeCheck, RejectsMismatchedFaces) {
  std::array<Texture2D, 6> faces;
  for (auto& f : faces) f = Texture2D(4, 4, TexelFormat::d32f);
  faces[3] = Texture2D(2, 2, TexelFormat::d32f);
  EXPECT_THROW(TextureCube{faces}, std::invalid_argument);
  faces[3] = Texture2D(4, 4, TexelFormat::d16);
  EXPECT_THROW(TextureCube{faces}, std::invalid_argument);
  for (auto& f : faces) f = Texture2D(4, 2, TexelFormat::d32f);
  EXPECT_THROW(TextureCube{faces}, std::invalid_argument);
}

}  // namespace
