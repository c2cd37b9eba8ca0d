// Building one caster's projective map: a small RGBA8 colour target cleared to white with the caster drawn
// into it in black (grey for non-opaque parts) through its fitted frustum, an outer ring of texels kept white
// by the frustum's margin and by a scissor, optionally blurred by drawing it onto itself at an offset
// (offset_blur.h), and (when the lookup blurs) a box-filtered mip chain whose edge texels stay white too. Like the article's software rasterizer for shadow maps: no depth buffer, flat colour.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/renderer.h"
#include "shading/surface_texture.h"
#include "shading/texture.h"
#include "shading/techniques/projective_frustum.h"
#include "shading/techniques/projective_types.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// One piece of a caster in world space with the grey it is drawn with.
struct CasterPart {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  float shade = 0.0f;
  // An alpha-masked part: its texture coordinates (one per position) and alpha test; drawn undecimated with
  // the test in front of the mask shader (masked_depth.h). Null: opaque.
  std::vector<glm::vec2> texcoords;
  const SurfaceTexture* alpha = nullptr;
};

// How many mip levels a lookup may read and how wide the white ring must be for every one of them to have
// white edge texels: ring = the level-0 texels that reach the last level's edge texel through the box filter
// (odd sides cover more than two texels, partly). max_level = ceil(lod_bias), reduced until an inner texel is
// left.
struct MipPlan {
  int ring = 1;
  int max_level = 0;
};
MipPlan plan_mips(int map_size, float lod_bias);

struct CasterMap {
  CasterFrustum frustum;
  Box bounds;                                   // the caster's world bounds the frustum was fitted to
  std::unique_ptr<raster::ColorTarget> target;  // held by pointer: `texture` views it
  Texture2D texture;                            // level 0 views `target`; levels 1.. owned (when blurred)
  MipPlan mips;
  int blur_passes = 0;                          // offset-blur passes run (settings' count, fewer on tiny maps)
  uint64_t triangles = 0;                       // triangles drawn into the map (after decimation)
};

// The flat-colour shader the map is drawn with.
struct CasterMaskShader {
  using Vertex = glm::vec3;
  struct Varyings {
    float unused;
  };
  glm::mat4 view_proj{1.0f};
  float shade = 0.0f;
  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    out.unused = 0.0f;
    return view_proj * glm::vec4(v, 1.0f);
  }
  void fragment(const raster::QuadIn<Varyings>&, raster::QuadOut& out) const {
    for (auto& c : out.color) c = glm::vec4(shade, shade, shade, 1.0f);
  }
};

// Fits the frustum to `bounds` inside a white ring of mips.ring + blur_passes texels, draws every part
// (decimated to the map's resolution when settings.decimate), runs the offset-blur passes, builds the mips the
// plan asks for. A caster the frustum cannot hold (light inside its bounds) gets an
// all-white map and an invalid frustum.
CasterMap build_caster_map(raster::Renderer& renderer, const ProjectiveLight& light,
                           const ProjectiveSettings& settings, const Box& bounds, std::span<const CasterPart> parts);

SHADOWLAB_ISA_END
}  // namespace shading::tech
