// The back end of a shaded draw: covered pixels of a block grouped into 2×2 quads, early depth test when the
// shader allows it, the shader run on the quad (helper lanes included), late depth test, depth write, and the
// colour write with blending.
#pragma once
#include <cmath>
#include <cstdint>

#include "raster/depth_test.h"
#include "raster/interpolation.h"
#include "raster/quad.h"
#include "raster/shader.h"
#include "raster/state.h"
#include "raster/target.h"

namespace raster {

// Scalar depth test of one pixel, same conversion and comparison as the SIMD path.
template <DepthFormat Format, DepthFunc Func>
struct ScalarDepth {
  using Storage = typename DepthTraits<Format>::Storage;
  static auto convert(float z) {
    if constexpr (Format == DepthFormat::d16) return int32_t(std::nearbyint(z * 65535.0f));
    else if constexpr (Format == DepthFormat::d24) return int32_t(std::nearbyint(z * 16777215.0f));
    else return z;
  }
  static bool test(decltype(convert(0.0f)) f, decltype(convert(0.0f)) s) {
    if constexpr (Func == DepthFunc::never) return false;
    if constexpr (Func == DepthFunc::always) return true;
    if constexpr (Func == DepthFunc::less) return f < s;
    if constexpr (Func == DepthFunc::greater) return f > s;
    if constexpr (Func == DepthFunc::equal) return f == s;
    if constexpr (Func == DepthFunc::notequal) return f != s;
    if constexpr (Func == DepthFunc::lequal) return f <= s;
    if constexpr (Func == DepthFunc::gequal) return f >= s;
  }
  static decltype(convert(0.0f)) load(const Storage* p) {
    if constexpr (Format == DepthFormat::d32f) return *p;
    else return int32_t(*p);
  }
};

inline float clamp01(float z) { return z < 0.0f ? 0.0f : (z > 1.0f ? 1.0f : z); }

// Same operation order as plane_depth_columns + plane_depth_clamped (depth_stage.h), one pixel.
inline float plane_depth(const TriangleSetup& t, int32_t x, int32_t y) {
  const float zcol = std::fma(t.dzdx, float(x), t.z_a0);
  return clamp01(std::fma(t.dzdy, float(y), zcol) + t.z_offset);
}

template <class Shader, DepthFormat Format, DepthFunc Func>
struct ShadedStage {
  using V = typename Shader::Varyings;
  using SD = ScalarDepth<Format, Func>;
  static constexpr bool kEarlyZ = !shader_discards<Shader>() && !shader_writes_depth<Shader>();

  const Shader* shader;
  const TriangleInterp<V>* interps;  // of the chunk being executed
  DepthTarget* depth;                // may be null (no depth buffer: test always passes, nothing written)
  ColorTarget* color;                // may be null
  bool depth_write, color_write;
  BlendMode blend;

  void block(const TriangleSetup& t, int32_t bx, int32_t by, uint64_t mask) const {
    for (int p = 0; p < 4; ++p) {
      const unsigned m0 = unsigned(mask >> (16 * p)) & 0xFFu, m1 = unsigned(mask >> (16 * p + 8)) & 0xFFu;
      if (!(m0 | m1)) continue;
      for (int q = 0; q < 4; ++q) {
        const unsigned live = ((m0 >> (2 * q)) & 3u) | (((m1 >> (2 * q)) & 3u) << 2);
        if (live) quad(t, bx + 2 * q, by + 2 * p, live);
      }
    }
  }

  void quad(const TriangleSetup& t, int32_t x, int32_t y, unsigned live) const {
    using Storage = typename SD::Storage;
    float z[4];
    for (int l = 0; l < 4; ++l) z[l] = plane_depth(t, x + (l & 1), y + (l >> 1));
    if constexpr (kEarlyZ) {
      if (depth) live &= depth_mask(x, y, z, live);
      if (!live) return;
    }
    QuadIn<V> in;
    in.live = uint8_t(live);
    in.front_facing = !(t.prim & kBackFacingBit);
    const TriangleInterp<V>& ti = interps[t.prim & ~kBackFacingBit];
    for (int l = 0; l < 4; ++l) {
      const float px = float(x + (l & 1)) + 0.5f, py = float(y + (l >> 1)) + 0.5f;
      const float inv_w = interpolate(ti, px, py, in.in[l]);
      in.frag_coord[l] = glm::vec4(px, py, z[l], inv_w);
    }
    QuadOut out;
    shader->fragment(in, out);
    if constexpr (shader_discards<Shader>()) live &= ~unsigned(out.discard);
    if constexpr (shader_writes_depth<Shader>()) {
      for (int l = 0; l < 4; ++l) z[l] = clamp01(out.depth[l]);
    }
    if constexpr (!kEarlyZ) {
      if (depth) live &= depth_mask(x, y, z, live);
    }
    if (!live) return;
    for (int l = 0; l < 4; ++l) {
      if (!(live >> l & 1u)) continue;
      const int32_t px = x + (l & 1), py = y + (l >> 1);
      if (depth && depth_write && Func != DepthFunc::never) {
        Storage* d = depth->row<Storage>(py) + px;
        *d = Storage(SD::convert(z[l]));
      }
      if (color && color_write) write_color(px, py, out.color[l]);
    }
  }

  unsigned depth_mask(int32_t x, int32_t y, const float* z, unsigned live) const {
    unsigned pass = 0;
    for (int l = 0; l < 4; ++l) {
      if (!(live >> l & 1u)) continue;
      const auto* d = depth->row<typename SD::Storage>(y + (l >> 1)) + x + (l & 1);
      if (SD::test(SD::convert(z[l]), SD::load(d))) pass |= 1u << l;
    }
    return pass;
  }

  void write_color(int32_t x, int32_t y, const glm::vec4& c) const {
    if (blend == BlendMode::multiply) {
      color->write(x, y, c * color->read(x, y));
    } else {
      color->write(x, y, c);
    }
  }
};

}  // namespace raster
