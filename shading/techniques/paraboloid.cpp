// Planning, building and reader setup of the dual-paraboloid shadow map (see paraboloid.h).
#include "shading/techniques/paraboloid.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

LightFrame paraboloid_frame(const OmniLight& light, const OmniSettings& s) {
  const glm::vec3 axis = !light.hemispherical && s.split_normal ? *s.split_normal : light.direction;
  return light_frame(light.position, axis);
}

ShadowMapSet plan_paraboloid_map(const OmniLight& light, const OmniSettings& s) {
  const int n = s.map_size;
  const int maps = light.hemispherical ? 1 : 2;
  ShadowMapSet set;
  set.targets.push_back(std::make_unique<raster::DepthTarget>(maps * n, n, s.depth_format));
  if (s.packing == DepthPacking::rgba8)
    set.colors.push_back(std::make_unique<raster::ColorTarget>(maps * n, n, raster::ColorFormat::rgba8));
  const glm::mat4 view = paraboloid_frame(light, s).matrix();
  for (int k = 0; k < maps; ++k) {
    ShadowPass p;
    p.label = k == 0 ? "front" : "back";
    p.viewport = raster::Rect{k * n, 0, n, n};
    p.view = view;
    if (k == 1) p.view = glm::mat4(1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f,
                                   0.0f, 1.0f) * view;
    set.passes.push_back(p);
  }
  return set;
}

raster::DrawStats build_paraboloid_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                       const OmniSettings& s, const CasterGeometry& casters) {
  const glm::mat4 to_light = paraboloid_frame(light, s).matrix();
  float side = 1.0f;
  auto draw = [&]<bool kPack>() {
    return draw_omni_passes(
        renderer, set, casters, s.cull_front,
        [&](const ShadowPass&) {
          const ParaboloidDepthShader<kPack> sh{to_light, side, 1.0f / light.range};
          side = -side;
          return sh;
        },
        // Cleared to (1, 1, 1, 1), which unpacks to just over 1 (the pack cannot hold 1.0 itself: it gives 0).
        glm::vec4(1.0f));
  };
  if (s.packing == DepthPacking::rgba8) return draw.template operator()<true>();
  return draw.template operator()<false>();
}

Texture2D paraboloid_depth_texture(const ShadowMapSet& set, size_t pass, const OmniSettings& s) {
  const ShadowPass& p = set.passes.at(pass);
  if (s.packing != DepthPacking::rgba8) return Texture2D::view(*set.targets.at(p.target), p.viewport);
  const raster::ColorTarget& c = *set.colors.at(p.target);
  const raster::Rect& v = p.viewport;
  Texture2D t(v.width, v.height, TexelFormat::d32f);
  for (int j = 0; j < v.height; ++j)
    for (int i = 0; i < v.width; ++i) t.set_texel(i, j, glm::vec4(unpack_depth_rgba8(c.read(v.x + i, v.y + j))));
  return t;
}

OmniReader make_paraboloid_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s) {
  OmniReader r = omni_reader_base(OmniKind::paraboloid, paraboloid_frame(light, s), light, s);
  r.has_back = set.passes.size() > 1;
  for (size_t k = 0; k < set.passes.size() && k < 2; ++k) {
    const Texture2D tex = paraboloid_depth_texture(set, k, s);
    r.maps[k] = map_lookups(tex, Wrap::clamp_to_edge);
  }
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
