// Building shadow maps: depth-only draws of world-space triangles, one per pass (see depth_pass.h).
#include "shading/techniques/depth_pass.h"

#include "shading/techniques/masked_depth.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

ShadowMapSet single_map_layout(int size, raster::DepthFormat format, const char* label) {
  ShadowMapSet set;
  set.targets.push_back(std::make_unique<raster::DepthTarget>(size, size, format));
  ShadowPass p;
  p.label = label;
  p.viewport = raster::Rect{0, 0, size, size};
  set.passes.push_back(p);
  return set;
}

raster::DrawStats build_maps(raster::Renderer& renderer, ShadowMapSet& set, const CasterGeometry& casters,
                             const DepthPassOptions& options) {
  for (auto& t : set.targets) t->clear(1.0f);
  raster::DrawStats stats;
  for (const ShadowPass& p : set.passes) {
    raster::DrawState s;
    s.viewport = p.viewport;
    s.scissor = p.viewport;  // a pass never writes outside its own region
    s.cull = options.cull_front ? raster::CullMode::front : raster::CullMode::none;
    s.polygon_offset = options.offset;
    s.color_write = false;
    stats += draw_casters(renderer, raster::RenderTargets{set.targets[p.target].get(), nullptr}, s,
                          WorldDepthShader{p.proj * p.view}, casters);
  }
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
