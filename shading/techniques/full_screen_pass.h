// The shape every full-screen pass of the techniques shares (the filterable maps' encode and blur passes,
// blur_pass.*; the projective maps' offset blur, offset_blur.*): one triangle covering the viewport, drawn
// without depth, with a fragment shader that computes each pixel from the integer pixel alone. Written once so
// the quad and the wide (quad pair) paths of every such pass compute the same values bit for bit.
#pragma once
#include <array>

#include <glm/vec4.hpp>

#include "raster/renderer.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// One triangle covering the whole viewport; the pipeline clips it to the viewport like any other.
inline constexpr std::array<glm::vec4, 3> kFullScreenTriangle = {
    glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f), glm::vec4(3.0f, -1.0f, 0.0f, 1.0f), glm::vec4(-1.0f, 3.0f, 0.0f, 1.0f)};

// No depth test or write: a pass writes every pixel of its target.
inline raster::DrawState full_screen_state() {
  raster::DrawState s;
  s.depth_test = false;
  s.depth_write = false;
  return s;
}

// Both fragment stages of a full-screen shader from one per-texel function `texel(x, y)` of the integer pixel
// (gl_FragCoord − 0.5), so the quad and the wide path compute the same values bit for bit. A shader may still
// define its own fragment_pair (blur_pass.cpp's box filter does) as long as it keeps that promise.
template <class Derived>
struct FullScreenShader {
  using Vertex = glm::vec4;
  using Varyings = raster::NoVaryings;
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (size_t l = 0; l < 4; ++l)
      out.color[l] = self().texel(int(q.frag_coord[l].x), int(q.frag_coord[l].y));
  }
  void fragment_pair(const raster::QuadPairIn<Varyings>& q, raster::QuadPairOut& out) const {
    alignas(32) float fx[8], fy[8], ch[4][8];
    q.frag_x.store(fx), q.frag_y.store(fy);
    for (int l = 0; l < 8; ++l) {
      const glm::vec4 t = self().texel(int(fx[l]), int(fy[l]));
      for (int c = 0; c < 4; ++c) ch[c][l] = t[c];
    }
    for (size_t c = 0; c < 4; ++c) out.color[c] = raster::simd::VecF32::load(ch[c]);
  }
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

// Draws shader `s` over the whole of `dst`.
template <class Shader>
raster::DrawStats draw_full_screen(raster::Renderer& renderer, raster::ColorTarget& dst, const Shader& s) {
  return renderer.draw(raster::RenderTargets{nullptr, &dst}, full_screen_state(), s,
                       std::span<const glm::vec4>(kFullScreenTriangle));
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
