// Test helpers for raster/: a brute-force reference rasterizer written straight from CONVENTIONS (one pixel at a
// time, int64 edge functions, no tiles, no SIMD), a shader that counts how often each pixel is shaded, and
// small geometry builders.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/renderer.h"

namespace rtest {

// A window vertex at sub-pixel position (sx, sy) with depth z, as triangle setup takes it (w = 1).
inline raster::WindowVertex snapped_vertex(int32_t sx, int32_t sy, float z) {
  raster::WindowVertex v{};
  v.x = float(sx) / float(raster::kSubpixelScale), v.y = float(sy) / float(raster::kSubpixelScale), v.z = z;
  v.inv_w = 1.0f;
  v.sx = sx, v.sy = sy;
  return v;
}

// Window point (x, y) of a W×H viewport at origin 0, as a clip-space position with the given w.
inline glm::vec4 win_to_clip(double x, double y, int w, int h, double z_ndc = 0.0, double cw = 1.0) {
  return glm::vec4(float((x / w * 2.0 - 1.0) * cw), float((y / h * 2.0 - 1.0) * cw), float(z_ndc * cw), float(cw));
}

// Coverage of one unclipped triangle (all w > 0), by definition: snap, then test every pixel centre with exact
// edge functions and the tie rule. Returns a W×H mask (row 0 = bottom) and fills `area_sign`.
inline std::vector<uint8_t> reference_coverage(const glm::vec4 c[3], int W, int H, int* area_sign = nullptr) {
  int64_t X[3], Y[3];
  for (int k = 0; k < 3; ++k) {
    const float iw = 1.0f / c[k].w;
    const float xw = std::fma(c[k].x * iw, W * 0.5f, W * 0.5f);
    const float yw = std::fma(c[k].y * iw, H * 0.5f, H * 0.5f);
    X[k] = int64_t(std::nearbyint(double(xw) * 256.0));
    Y[k] = int64_t(std::nearbyint(double(yw) * 256.0));
  }
  std::vector<uint8_t> mask(size_t(W) * H, 0);
  const int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area_sign) *area_sign = area > 0 ? 1 : (area < 0 ? -1 : 0);
  if (area == 0) return mask;
  int o[3] = {0, 1, 2};
  if (area < 0) std::swap(o[1], o[2]);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const int64_t px = 256 * int64_t(i) + 128, py = 256 * int64_t(j) + 128;
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        const int a = o[e], b = o[(e + 1) % 3];
        // Counter-clockwise: interior on the left of a→b. E > 0 inside; E == 0 belongs to left edges
        // (going down, Y_a > Y_b) and to horizontal edges with the interior above (going right, X_b > X_a).
        const int64_t E = (X[b] - X[a]) * (py - Y[a]) - (Y[b] - Y[a]) * (px - X[a]);
        const bool left = Y[a] > Y[b];
        const bool bottom = Y[a] == Y[b] && X[b] > X[a];
        inside = E > 0 || (E == 0 && (left || bottom));
      }
      mask[size_t(j) * W + i] = inside;
    }
  return mask;
}

// A shader that counts fragments per pixel (helper lanes excluded): its fragment stage adds one for every live
// lane. Run it with depth testing off to count coverage exactly.
struct CountingShader {
  using Vertex = glm::vec4;
  using Varyings = raster::NoVaryings;
  uint32_t* counts;
  int width;
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (int l = 0; l < 4; ++l) {
      out.color[l] = glm::vec4(1.0f);
      if (q.live >> l & 1) ++counts[size_t(q.frag_coord[l].y) * width + size_t(q.frag_coord[l].x)];
    }
  }
};

// ClipSpaceDepthShader's flat-white twin with a fragment stage: its draws go through the shaded back end, which
// tests every pixel and never consults hierarchical depth, and through the front end one triangle at a time.
struct WhiteShader {
  using Vertex = glm::vec4;
  using Varyings = raster::NoVaryings;
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
  void fragment(const raster::QuadIn<Varyings>&, raster::QuadOut& out) const {
    for (auto& c : out.color) c = glm::vec4(1.0f);
  }
};

// Runs CountingShader over the triangles and returns the per-pixel counts.
inline std::vector<uint32_t> count_coverage(raster::Renderer& r, int W, int H, const std::vector<glm::vec4>& pos,
                                            const std::vector<uint32_t>& idx, raster::DrawState state = {}) {
  std::vector<uint32_t> counts(size_t(W) * H, 0);
  raster::ColorTarget color(W, H, raster::ColorFormat::rgba8);
  state.depth_test = false;
  r.draw(raster::RenderTargets{nullptr, &color}, state, CountingShader{counts.data(), W},
         std::span<const glm::vec4>(pos), idx);
  return counts;
}

// FNV-1a over the stored bytes of a depth target's visible texels.
inline uint64_t hash_depth(const raster::DepthTarget& d) {
  uint64_t h = 1469598103934665603ull;
  for (int y = 0; y < d.height(); ++y)
    for (int x = 0; x < d.width(); ++x) {
      uint32_t v = d.raw(x, y);
      for (int b = 0; b < 4; ++b) h = (h ^ ((v >> (8 * b)) & 0xFF)) * 1099511628211ull;
    }
  return h;
}

}  // namespace rtest
