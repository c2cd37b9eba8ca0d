// Layout, building and export of a view-following technique's maps (see slice_set.h).
#include "shading/techniques/slice_set.h"

#include <algorithm>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

SliceSet::SliceSet(Technique technique, std::vector<FittedMap> fits, std::vector<std::string> labels,
                   const LightDesc& light, const ShadowConfig& c, bool atlas)
    : technique_(technique), fits_(std::move(fits)) {
  const int n = c.map_size, count = int(fits_.size());
  const int cols = atlas ? std::min(count, 2) : 1, rows = atlas ? (count + 1) / 2 : 1;
  if (atlas) set_.targets.push_back(std::make_unique<raster::DepthTarget>(cols * n, rows * n, c.depth_format));
  for (int k = 0; k < count; ++k) {
    ShadowPass p;
    p.label = labels.at(size_t(k));
    if (atlas) {
      p.target = 0;
      p.viewport = raster::Rect{(k % 2) * n, (k / 2) * n, n, n};
    } else {
      p.target = set_.targets.size();
      set_.targets.push_back(std::make_unique<raster::DepthTarget>(n, n, c.depth_format));
      p.viewport = raster::Rect{0, 0, n, n};
    }
    p.view = fits_[size_t(k)].view;
    p.proj = fits_[size_t(k)].proj;
    p.perspective = fits_[size_t(k)].perspective;
    set_.passes.push_back(p);
  }
  options_.cull_front = c.cull_front;
  if (c.bias.mode == BiasMode::offset) options_.offset = raster::PolygonOffset{c.bias.offset_factor, c.bias.offset_units};
  light_ = SliceLight{glm::normalize(light.direction), c.bias, c.filter, c.filter_params};
}

raster::DrawStats SliceSet::build(raster::Renderer& renderer, const CasterGeometry& c) {
  const raster::DrawStats stats = build_maps(renderer, set_, c, options_);
  maps_.clear();
  for (size_t k = 0; k < fits_.size(); ++k) maps_.push_back(make_slice_map(set_, k, fits_[k].depth_extent));
  return stats;
}

std::vector<MapRecord> SliceSet::records() const {
  std::vector<MapRecord> out;
  for (size_t t = 0; t < set_.targets.size(); ++t) {
    MapRecord m;
    m.target = set_.targets[t].get();
    m.technique = to_string(technique_);
    m.encoding = info(technique_).encoding;
    for (const ShadowPass& p : set_.passes) {
      if (p.target != t) continue;
      if (m.passes.empty()) m.world_to_camera = p.view, m.world_to_ndc = p.proj * p.view;  // the first pass's
      m.passes.push_back(MapPassRecord{p.label, p.viewport, p.view, p.proj * p.view});
    }
    if (set_.passes.size() == 1) m.passes.clear();  // a single full-image pass: no list
    out.push_back(std::move(m));
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
