// Planning, building and reader setup of the cube shadow map (see cube_map.h).
#include "shading/techniques/cube_map.h"

#include <algorithm>
#include <array>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/trigonometric.hpp>

#include "shading/techniques/moment_lod.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {
const char* const kFaceLabels[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
}

ShadowMapSet plan_cube_map(const OmniLight& light, const OmniSettings& s) {
  const int n = s.map_size;
  ShadowMapSet set;
  set.targets.push_back(std::make_unique<raster::DepthTarget>(3 * n, 2 * n, s.depth_format));
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, s.near_plane, light.range);
  for (int f = 0; f < 6; ++f) {
    ShadowPass p;
    p.label = kFaceLabels[f];
    p.viewport = raster::Rect{n * (f % 3), n * (f / 3), n, n};
    p.view = cube_face_view(f, light.position);
    p.proj = proj;
    p.perspective = true;
    set.passes.push_back(p);
  }
  return set;
}

raster::DrawStats build_cube_map(raster::Renderer& renderer, ShadowMapSet& set, const OmniLight& light,
                                 const OmniSettings& s, const CasterGeometry& casters) {
  return draw_omni_passes(renderer, set, casters, s.cull_front, [&](const ShadowPass& p) {
    return RadialDepthShader{p.proj * p.view, light.position, 1.0f / light.range};
  });
}

TextureCube cube_texture(const ShadowMapSet& set) {
  std::array<Texture2D, 6> faces;
  for (int f = 0; f < 6; ++f) {
    const ShadowPass& p = set.passes.at(size_t(f));
    faces[size_t(f)] = Texture2D::view(*set.targets.at(p.target), p.viewport);
  }
  return TextureCube(std::move(faces));
}

raster::DrawStats build_cube_moments(raster::Renderer& renderer, const ShadowMapSet& set, bool seamless,
                                     CubeMoments& m) {
  raster::DrawStats stats;
  std::array<Texture2D, 6> views;
  for (size_t f = 0; f < 6; ++f) {
    stats += filter_pass(renderer, set, f, LightDepth{}, m.params, m.blur_radius, m.faces[f]);
    views[f] = m.faces[f].view;
  }
  m.cube = TextureCube(std::move(views));
  m.sampler = moment_sampler(m.params.mips);
  m.sampler.seamless_cube = seamless;
  return stats;
}

float cube_moment_visibility(const OmniReader& r, const CubeMoments& m, const ShadowQuery& q) {
  const OmniRef o = omni_ref(r, q.p, q.n);
  const glm::vec3 d = o.q - r.position;
  if (r.hemispherical && glm::dot(d, r.direction) < 0.0f) return 0.0f;
  const float ref = glm::length(d) / r.range - o.bias;
  // The direction's derivatives are the point's: GL's cube LOD on the face d selects (lookup_cube.h).
  const glm::vec4 moments = m.cube.levels() > 1 && m.sampler.mip_filter != MipFilter::none
                                ? texture_grad(m.cube, m.sampler, d, q.dpdx, q.dpdy)
                                : texture_at(m.cube, m.sampler, d, 0.0f);
  return moment_visibility(m.params, moments, std::min(ref, 1.0f));
}

OmniReader make_cube_reader(const ShadowMapSet& set, const OmniLight& light, const OmniSettings& s) {
  OmniReader r = omni_reader_base(OmniKind::cube, light_frame(light.position, light.direction), light, s);
  r.cube = cube_texture(set);
  r.cube_linear = Sampler::pcf(CompareFunc::lequal, Wrap::clamp_to_edge, 1.0f);
  r.cube_linear.seamless_cube = s.seamless;
  r.cube_nearest = r.cube_linear;
  r.cube_nearest.mag_filter = r.cube_nearest.min_filter = Filter::nearest;
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
