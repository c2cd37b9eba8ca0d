// Depth passes over alpha-masked casters: MaskedDepthShader<S> is any depth shader S of a map (the window-depth
// shader, the radial distance of cube and pyramid maps, the paraboloid warp) with the material's alpha test in
// front of S's own fragment stage, so a texel is written only where the caster's alpha passes. Discarding turns
// off early depth testing for those draws alone: draw_casters sends the opaque triangles through S itself, which
// without a fragment stage stays on the lean depth-only path.
#pragma once
#include <span>

#include <glm/vec4.hpp>

#include "raster/renderer.h"
#include "raster/shader.h"
#include "shading/techniques/caster_geometry.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

template <class S>
struct MaskedDepthShader {
  static_assert(std::is_same_v<typename S::Vertex, glm::vec3>, "a depth shader of world positions");
  using Vertex = MaskedVertex;
  struct Varyings {
    glm::vec2 st;
    [[no_unique_address]] typename S::Varyings inner;  // S's own varyings after st (none: st alone)
  };
  static constexpr bool kDiscards = true;
  static constexpr bool kWritesDepth = raster::shader_writes_depth<S>();

  S shader;
  const SurfaceTexture* alpha = nullptr;

  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    out.st = v.st;
    return shader.vertex(v.position, out.inner);
  }

  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    const Quad<glm::vec2> st{q.in[0].st, q.in[1].st, q.in[2].st, q.in[3].st};
    out.discard = alpha->discarded(alpha->color(st));
    if constexpr (raster::HasFragmentStage<S>) {
      raster::QuadIn<typename S::Varyings> in;
      for (size_t l = 0; l < 4; ++l) in.in[l] = q.in[l].inner;
      in.frag_coord = q.frag_coord;
      in.live = q.live;
      in.front_facing = q.front_facing;
      raster::QuadOut o;
      shader.fragment(in, o);
      out.color = o.color;
      out.depth = o.depth;
      if constexpr (raster::shader_discards<S>()) out.discard = uint8_t(out.discard | o.discard);
    }
  }
};

// Draws the casters into `targets` with shader S: the opaque triangles as S, every masked material's as
// MaskedDepthShader<S>, with the same state.
template <class S>
raster::DrawStats draw_casters(raster::Renderer& renderer, const raster::RenderTargets& targets,
                               const raster::DrawState& state, const S& shader, const CasterGeometry& casters) {
  raster::DrawStats stats = renderer.draw(targets, state, shader, casters.positions, casters.indices);
  for (const MaskedCasters& m : casters.masked)
    stats += renderer.draw(targets, state, MaskedDepthShader<S>{shader, m.alpha}, m.vertices, m.indices);
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
