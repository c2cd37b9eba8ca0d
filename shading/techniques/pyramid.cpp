// Planning, building and reader setup of the pyramid shadow map (see pyramid.h).
#include "shading/techniques/pyramid.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {
const char* const kLabels[4] = {"1 top", "2 right", "3 bottom", "4 left"};
}

PyramidPassCamera pyramid_pass_camera(int region, int size) {
  const float r = 1.0f / std::sqrt(2.0f);
  const float fov90 = glm::radians(90.0f), fov_wide = 2.0f * std::atan(std::sqrt(2.0f));
  const int h = size / 2;
  switch (region) {
    case 0:  // rotation (45°, 0): looks between +z and +y, up towards +y; the top half
      return {{0.0f, r, r}, {0.0f, r, -r}, fov90, std::sqrt(2.0f), {0, h, size, h}};
    case 1:  // rotation (0, −45°): between +z and +x; the right half
      return {{r, 0.0f, r}, {0.0f, 1.0f, 0.0f}, fov_wide, 1.0f / std::sqrt(2.0f), {h, 0, h, size}};
    case 2:  // rotation (−45°, 0): between +z and −y; the bottom half
      return {{0.0f, -r, r}, {0.0f, r, r}, fov90, std::sqrt(2.0f), {0, 0, size, h}};
    default:  // rotation (0, 45°): between +z and −x; the left half
      return {{-r, 0.0f, r}, {0.0f, 1.0f, 0.0f}, fov_wide, 1.0f / std::sqrt(2.0f), {0, 0, h, size}};
  }
}

ShadowMapSet plan_pyramid_map(const OmniLight& light, const OmniSettings& s) {
  const int n = s.map_size;
  ShadowMapSet set;
  set.targets.push_back(std::make_unique<raster::DepthTarget>(n, n, s.depth_format));
  const LightFrame f = light_frame(light.position, light.direction);
  for (int k = 0; k < 4; ++k) {
    const PyramidPassCamera c = pyramid_pass_camera(k, n);
    ShadowPass p;
    p.label = kLabels[k];
    p.viewport = c.viewport;
    p.view = glm::lookAt(light.position, light.position + f.to_world_dir(c.forward), f.to_world_dir(c.up));
    p.proj = glm::perspective(c.fov_y, c.aspect, s.near_plane, light.range);
    p.perspective = true;
    set.passes.push_back(p);
  }
  return set;
}

raster::DrawStats build_pyramid_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                    const OmniSettings& s, const CasterGeometry& casters) {
  const float center = 0.5f * float(set.targets.at(0)->width());
  int k = 0;
  return draw_omni_passes(renderer, set, casters, s.cull_front, [&](const ShadowPass& p) {
    return PyramidDepthShader{RadialDepthShader{p.proj * p.view, light.position, 1.0f / light.range}, k++, center};
  });
}

OmniReader make_pyramid_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s) {
  OmniReader r = omni_reader_base(OmniKind::pyramid, light_frame(light.position, light.direction), light, s);
  r.hemispherical = true;  // a 180° map: everything behind the light is unlit, whatever the light type
  r.maps[0] = map_lookups(Texture2D::view(*set.targets.at(0)), Wrap::clamp);  // legacy GL_CLAMP
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
