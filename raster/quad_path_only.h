// A shader adaptor for tests of the wide fragment path: QuadPathOnly<S> is S without fragment_pair, so the
// pipeline (fragment_stage.h) runs S::fragment() on 2×2 quads even where S has the wide form (shader.h).
#pragma once
#include <glm/vec4.hpp>

#include "raster/quad.h"
#include "raster/shader.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

template <class S>
struct QuadPathOnly {
  using Vertex = typename S::Vertex;
  using Varyings = typename S::Varyings;
  static constexpr bool kDiscards = shader_discards<S>();
  static constexpr bool kWritesDepth = shader_writes_depth<S>();
  S shader;
  glm::vec4 vertex(const Vertex& v, Varyings& out) const { return shader.vertex(v, out); }
  void fragment(const QuadIn<Varyings>& q, QuadOut& out) const { shader.fragment(q, out); }
};

SHADOWLAB_ISA_END
}  // namespace raster
