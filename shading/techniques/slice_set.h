// The maps of a view-following technique (cascades, LiSPSM, frustum faces): one pass per slice with its fitted
// matrices (view_fit.h), laid out either in one atlas target (viewport splitting, two slices per row) or in
// separate targets; built with the classic depth-pass state (back faces, polygon offset); read per slice through
// SliceMap (slice_read.h); exported as one record per target listing each of its passes.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "raster/renderer.h"
#include "shading/techniques/depth_pass.h"
#include "shading/techniques/slice_read.h"
#include "shading/techniques/technique.h"
#include "shading/techniques/view_fit.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

class SliceSet {
 public:
  SliceSet(Technique technique, std::vector<FittedMap> fits, std::vector<std::string> labels,
           const LightDesc& light, const ShadowConfig& config, bool atlas);

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& casters);
  size_t size() const { return fits_.size(); }
  const FittedMap& fit(size_t k) const { return fits_.at(k); }
  const ShadowMapSet& set() const { return set_; }
  const SliceMap& map(size_t k) const { return maps_.at(k); }  // after build
  std::span<const SliceMap> maps() const { return maps_; }
  const SliceLight& light() const { return light_; }
  std::vector<MapRecord> records() const;

 private:
  Technique technique_;
  std::vector<FittedMap> fits_;
  ShadowMapSet set_;
  DepthPassOptions options_;
  SliceLight light_;
  std::vector<SliceMap> maps_;
};

SHADOWLAB_ISA_END
}  // namespace shading::tech
