// The contract between the pipeline and a programmable shader. A shader is a plain C++ type; the pipeline
// (Renderer::draw in renderer.h) is a template over it, so there is no virtual call per vertex or fragment, and
// a shader without a fragment stage compiles to the lean depth-only path (depth_stage.h).
//
//   struct MyShader {
//     using Vertex = MyVertex;                  // what the vertex buffer holds
//     struct Varyings { glm::vec3 n; glm::vec2 uv; };  // floats only; interpolated perspective-correctly
//     glm::vec4 vertex(const Vertex& v, Varyings& out) const;   // returns the clip-space position
//     // vertex() must be a pure function of the vertex and the shader's (snapshotted) members: shaded draws run
//     // it once per vertex, depth-only draws may run it again for a vertex (where two chunks' vertex ranges
//     // meet, and for triangles that need clipping), as GL allows a vertex shader to run more than once.
//     // Optional fragment stage, one 2×2 quad at a time (so it can take derivatives, see quad.h):
//     void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const;
//     // Optional wide form of the same fragment stage, two quads (4×2 pixels) in SIMD lanes (see quad.h). When
//     // present the pipeline calls it instead of fragment(); it must compute, lane by lane, what fragment() does.
//     void fragment_pair(const raster::QuadPairIn<Varyings>& q, raster::QuadPairOut& out) const;
//     static constexpr bool kDiscards = false;     // may set QuadOut::discard   (default false)
//     static constexpr bool kWritesDepth = false;  // writes QuadOut::depth      (default false)
//   };
//
// Early depth testing is used whenever the shader neither discards nor writes depth, as on a GPU.
#pragma once
#include <concepts>
#include <type_traits>

#include <glm/vec4.hpp>

#include "raster/quad.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Varyings of a shader that passes nothing to the fragment stage.
struct NoVaryings {};

template <class S>
concept VertexShader = requires(const S& s, const typename S::Vertex& v, typename S::Varyings& out) {
  { s.vertex(v, out) } -> std::convertible_to<glm::vec4>;
} && std::is_trivially_copyable_v<typename S::Varyings> &&
                       (std::is_empty_v<typename S::Varyings> || sizeof(typename S::Varyings) % sizeof(float) == 0);

template <class S>
concept HasFragmentStage = requires(const S& s, const QuadIn<typename S::Varyings>& q, QuadOut& o) {
  s.fragment(q, o);
};

// The shader has the wide fragment stage (fragment_pair) as well.
template <class S>
concept HasPairFragmentStage = HasFragmentStage<S> && requires(const S& s, const QuadPairIn<typename S::Varyings>& q,
                                                               QuadPairOut& o) { s.fragment_pair(q, o); };

template <class S>
constexpr bool shader_discards() {
  if constexpr (requires { S::kDiscards; }) return S::kDiscards;
  return false;
}

template <class S>
constexpr bool shader_writes_depth() {
  if constexpr (requires { S::kWritesDepth; }) return S::kWritesDepth;
  return false;
}

// The simplest shader: positions already in clip space, depth only. Used by depth passes that are given
// final matrices, by the conformance tests and by the benchmarks.
struct ClipSpaceDepthShader {
  using Vertex = glm::vec4;
  using Varyings = NoVaryings;
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
};

SHADOWLAB_ISA_END
}  // namespace raster
