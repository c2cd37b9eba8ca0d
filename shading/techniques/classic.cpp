// The classic technique's planning and reader setup (see classic.h).
#include "shading/techniques/classic.h"

namespace shading::tech {

ShadowMapSet plan_classic_map(const ClassicLight& light, const ClassicSettings& s, const ClassicFit& fit) {
  ShadowMapSet set = single_map_layout(s.map_size, s.depth_format);
  ShadowPass& p = set.passes[0];
  LightMatrices m;
  if (light.kind == LightKind::spot) {
    m = spot_frustum(light.position, light.direction, light.outer_angle, light.range);
    p.perspective = true;
  } else {
    m = fit.fixed ? *fit.fixed : fit_directional(light.direction, fit.receivers, fit.casters);
  }
  p.view = m.view;
  p.proj = m.proj;
  return set;
}

DepthPassOptions classic_depth_options(const ClassicSettings& s) {
  DepthPassOptions o;
  o.cull_front = s.cull_front;
  if (s.bias.kind == BiasKind::offset) o.offset = raster::PolygonOffset{s.bias.offset_factor, s.bias.offset_units};
  return o;
}

ClassicReader make_classic_reader(const ShadowMapSet& set, const ClassicLight& light, const ClassicSettings& s) {
  const ShadowPass& p = set.passes.at(0);
  const raster::DepthTarget& target = *set.targets.at(p.target);
  const Texture2D tex = Texture2D::view(target, p.viewport);
  ClassicReader r;
  r.shadow = shadow_matrix(p);
  r.perspective = p.perspective;
  r.kind = light.kind;
  r.position = light.position;
  r.direction = light.direction;
  r.bias = s.bias;
  r.filter_kind = s.filter;
  r.filter = s.filter_params;
  r.maps = map_lookups(tex, Wrap::clamp_to_border);  // outside a directional map: border depth 1, lit
  return r;
}

}  // namespace shading::tech
