// Cascaded shadow maps (seed 001, "Going further"; the zones of seed 003) and LiSPSM for a directional light:
// the part of the view frustum where receivers can be is cut into 1-4 slices by the practical split scheme,
// each slice gets its own map fitted to it (orthographic and tight, orthographic and stabilised, or warped by
// LiSPSM: "cascades in light-space perspective"), and each pixel reads the map of the slice its view distance
// falls in, blending into the next one over an optional band. LiSPSM alone is one slice over the whole range.
#pragma once
#include <memory>
#include <vector>

#include "shading/techniques/technique.h"
#include "shading/techniques/view_fit.h"
#include "shading/techniques/view_frustum.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct CascadeSettings {
  int count = 4;             // slices, 1-4
  float lambda = 0.75f;      // practical split scheme: 1 logarithmic, 0 uniform
  bool stabilize = false;    // texel-snapped squares around each slice's bounding sphere
  float blend = 0.0f;        // fraction of a slice, at its far end, blended into the next slice's map
  bool atlas = true;         // all maps in one target, or one target each
  bool visible = false;      // range and crops from the camera's visible samples instead of the frustum
  bool lispsm = false;       // each slice's map warped by LiSPSM
};

// What a plan decided, for the reader and for tests: the split distances (count + 1) and each slice's map.
struct CascadePlan {
  std::vector<float> splits;
  std::vector<FittedMap> fits;
};

// Throws TechniqueError when `visible` is asked and the caller offers no visible samples.
CascadePlan plan_cascade_fits(const LightDesc& light, const CascadeSettings& s, int map_size, const PlanInputs& in);

// The slice a point at view distance `distance` reads (the last one beyond the far split), and the weight of
// the next slice's map in its blend band (0 outside it).
struct SliceChoice {
  size_t slice = 0;
  float next_weight = 0.0f;
};
SliceChoice choose_slice(std::span<const float> splits, float blend, float distance);

// The registry's factories: cascades with its parameters; lispsm = one slice, warped.
std::unique_ptr<LightShadow> plan_cascades(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_lispsm(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
