// The vocabulary shared by the omnidirectional techniques (cube, dual paraboloid, pyramid): the point light as
// they see it, its settings, the light's own frame (+z the way it faces), the per-light reader that the camera
// pass snapshots once per frame, and the helper that draws every pass of a map with a technique's own shader.
// How each map is laid out, built and read lives in cube_map.h, paraboloid.h and pyramid.h; omni_read.h picks
// one of them, and the filter, once per batch of points.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/parallel_clear.h"
#include "raster/renderer.h"
#include "shading/sampler.h"
#include "shading/texture_cube.h"
#include "shading/techniques/masked_depth.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/shadow_map_set.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

enum class OmniKind : uint8_t { cube, paraboloid, pyramid };

// A point light (all around) or a hemispherical one (only the half space it faces is lit).
struct OmniLight {
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit; the hemispherical light's axis, the pyramid's tip
  float range = 10.0f;                     // distances are stored divided by it
  bool hemispherical = false;
};

// float: the distance in the depth target. rgba8: also packed into an RGBA8 colour target with the
// dual-paraboloid description's base-256 pack (paraboloid only).
enum class DepthPacking : uint8_t { float_depth, rgba8 };

struct OmniSettings {
  FilterKind filter = FilterKind::pcf;
  FilterParams filter_params;
  BiasParams bias;              // depth values are distance / range; `offset` is not available (see resolve)
  bool cull_front = false;      // back faces only into the map
  int map_size = 1024;          // texels per side: per cube face, per paraboloid, of the pyramid's square
  raster::DepthFormat depth_format = raster::DepthFormat::d24;
  bool seamless = true;         // cube: GL_TEXTURE_CUBE_MAP_SEAMLESS
  std::optional<glm::vec3> split_normal;  // paraboloid: front map's axis (default: the light's direction)
  DepthPacking packing = DepthPacking::float_depth;
  float near_plane = 0.01f;     // the source's 0.01 near distance of the perspective passes
};

// An orthonormal frame at the light: z = forward, y = up, x = cross(z, y). With x chosen that way a
// glm::lookAt camera looking along any direction f with up u (both given in this frame) has its right axis
// along the frame's x whenever the source's camera would, so the pyramid's regions read back unmirrored.
struct LightFrame {
  glm::vec3 origin{0.0f};
  glm::vec3 x{1.0f, 0.0f, 0.0f}, y{0.0f, 1.0f, 0.0f}, z{0.0f, 0.0f, 1.0f};
  glm::vec3 to_light(glm::vec3 p) const {
    const glm::vec3 d = p - origin;
    return {glm::dot(x, d), glm::dot(y, d), glm::dot(z, d)};
  }
  glm::vec3 to_world_dir(glm::vec3 v) const { return v.x * x + v.y * y + v.z * z; }
  glm::mat4 matrix() const;  // world → light frame (rows x, y, z; translation −origin)
};
LightFrame light_frame(glm::vec3 origin, glm::vec3 forward);

// What the camera pass reads for one omni light, copied once per frame. The set must outlive it.
struct OmniReader {
  OmniKind kind = OmniKind::cube;
  LightFrame frame;  // paraboloid: z = split normal; pyramid: z = the light's direction
  glm::vec3 position{0.0f}, direction{0.0f, -1.0f, 0.0f};
  float range = 10.0f;
  bool hemispherical = false;  // points behind the light's hemisphere are unlit
  BiasParams bias;
  FilterKind filter_kind = FilterKind::pcf;
  FilterParams filter;
  // cube
  TextureCube cube;
  Sampler cube_nearest, cube_linear;
  // paraboloid: [0] front, [1] back (absent for a hemispherical light); pyramid: [0]
  std::array<MapLookups, 2> maps;
  bool has_back = false;
};

// A reader with the fields every omni technique fills the same way (light, bias, filter); each technique then
// adds its maps.
OmniReader omni_reader_base(OmniKind kind, const LightFrame& frame, const OmniLight& light, const OmniSettings& s);

// The compare reference and the point it is taken at, with the reader's bias applied: the receiver moved along
// its normal (`normal`), or the reference lowered by depth_bias (constant, slope) with N·L towards the light.
struct OmniRef {
  glm::vec3 q;  // the point looked up (world)
  float bias;   // subtracted from distance / range
};
inline OmniRef omni_ref(const OmniReader& r, glm::vec3 p, glm::vec3 n) {
  OmniRef o{p, 0.0f};
  if (r.bias.mode == BiasMode::normal) {
    o.q = p + n * r.bias.normal_offset;
    return o;
  }
  const glm::vec3 l = r.position - p;
  const float len = glm::length(l);
  const float ndotl = len > 0.0f ? glm::dot(n, l) / len : 1.0f;
  switch (r.bias.mode) {
    case BiasMode::constant: o.bias = r.bias.constant; break;
    case BiasMode::slope: {
      const float c = ndotl < 0.0f ? 0.0f : (ndotl > 1.0f ? 1.0f : ndotl);
      const float v = r.bias.slope * std::tan(std::acos(c));
      o.bias = v < 0.0f ? 0.0f : (v > r.bias.slope_max ? r.bias.slope_max : v);
      break;
    }
    default: break;
  }
  return o;
}

// Draws every pass of `set` with the shader make(pass) returns, called once per pass (each pass in its viewport,
// scissored to it; masked casters with that shader's alpha-tested form, masked_depth.h),
// after clearing the depth targets to 1 and any colour targets to `clear_color`.
template <class MakeShader>
raster::DrawStats draw_omni_passes(raster::Renderer& renderer, ShadowMapSet& set, const CasterGeometry& casters,
                                   bool cull_front, MakeShader&& make,
                                   glm::vec4 clear_color = glm::vec4(1.0f)) {
  for (auto& t : set.targets) t->clear(1.0f);
  for (auto& c : set.colors)
    if (c) raster::clear_on_workers(*c, clear_color, renderer.pool());
  raster::DrawStats stats;
  for (size_t i = 0; i < set.passes.size(); ++i) {
    const ShadowPass& p = set.passes[i];
    raster::DrawState s;
    s.viewport = p.viewport;
    s.scissor = p.viewport;
    s.cull = cull_front ? raster::CullMode::front : raster::CullMode::none;
    raster::ColorTarget* color = p.target < set.colors.size() ? set.colors[p.target].get() : nullptr;
    s.color_write = color != nullptr;
    stats += draw_casters(renderer, raster::RenderTargets{set.targets[p.target].get(), color}, s, make(p), casters);
  }
  return stats;
}

// The radial distance shader of the cube and pyramid passes: the light-to-vertex vector as a varying, and the
// fragment's depth written as |P − light| / range (what the depth test compares and the map stores).
// kRegion >= 0: the pyramid's pass kRegion keeps only fragments in its own triangle (pyramid.h).
struct RadialDepthShader {
  using Vertex = glm::vec3;
  struct Varyings {
    glm::vec3 rel;
  };
  static constexpr bool kWritesDepth = true;
  glm::mat4 view_proj{1.0f};
  glm::vec3 light{0.0f};
  float inv_range = 1.0f;
  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    out.rel = v - light;
    return view_proj * glm::vec4(v, 1.0f);
  }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (size_t l = 0; l < 4; ++l) out.depth[l] = glm::length(q.in[l].rel) * inv_range;
  }
};

SHADOWLAB_ISA_END
}  // namespace shading::tech
