// A material's base colour as a shader reads it: the factor times a texture sampled at transformed texture
// coordinates (glTF's baseColorFactor × baseColorTexture, KHR_texture_transform), and the alpha test of a
// masked material. The camera pass takes colour and alpha from it; the shadow depth passes and the ray-cast
// reference only the alpha test, so a leaf card's shadow has the leaf's shape. Per-draw state, plain data.
#pragma once
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/fragment.h"
#include "shading/lookup.h"
#include "shading/sampler.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

struct SurfaceTexture {
  const Texture2D* texture = nullptr;  // null: the factor alone
  // glTF's default sampler: LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT (the wraps are the material's).
  Sampler sampler = Sampler::plain(Filter::linear, Wrap::repeat, MipFilter::linear);
  glm::mat3 transform{1.0f};  // (s, t, 1) -> the coordinates the texture is sampled at
  glm::vec4 factor{1.0f};     // linear RGBA
  bool masked = false;        // discard where alpha < cutoff
  float cutoff = 0.5f;

  glm::vec2 coords(glm::vec2 st) const { return glm::vec2(transform * glm::vec3(st, 1.0f)); }

  // Factor × texture at a quad's four lanes (helper lanes included, for the LOD), from untransformed (s, t).
  Quad<glm::vec4> color(const Quad<glm::vec2>& st) const {
    Quad<glm::vec4> c{factor, factor, factor, factor};
    if (!texture) return c;
    const Quad<glm::vec2> uv{coords(st[0]), coords(st[1]), coords(st[2]), coords(st[3])};
    const Quad<glm::vec4> t = shading::texture(*texture, sampler, uv);
    for (size_t l = 0; l < 4; ++l) c[l] *= t[l];
    return c;
  }

  // Factor × texture at one point, level 0 (where there is no quad to take a footprint from: a ray's hit).
  glm::vec4 color_at(glm::vec2 st) const {
    return texture ? factor * texture_lod(*texture, sampler, coords(st), 0.0f) : factor;
  }

  // Bit l set: lane l's alpha is below the cutoff (always 0 for a surface that is not masked).
  uint8_t discarded(const Quad<glm::vec4>& c) const {
    if (!masked) return 0;
    uint8_t bits = 0;
    for (int l = 0; l < 4; ++l)
      if (!(c[size_t(l)].a >= cutoff)) bits = uint8_t(bits | (1u << l));
    return bits;
  }
  bool discarded_at(glm::vec2 st) const { return masked && !(color_at(st).a >= cutoff); }
};

SHADOWLAB_ISA_END
}  // namespace shading
