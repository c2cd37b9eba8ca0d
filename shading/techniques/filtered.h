// The filterable shadow maps: exponential (ESM), variance (VSM) and exponential variance (EVSM, two or four
// moments) for directional and spot lights, on the classic technique's single map. Building is four passes on
// the pipeline: the depth pass (depth_pass.h, the classic state), the encode pass (depth → moments, a float
// target of the kind's channels) and the two blur passes (blur_pass.h), then the blurred map's mip chain.
// Reading is one lookup of the blurred moments per point, trilinear at the level of detail of the point's screen
// derivatives (moment_lod.h), and the kind's visibility formula (moments.h). Formulas, parameters and limits:
// docs/filtered-shadows.md.
#pragma once
#include <memory>
#include <optional>
#include <span>

#include <glm/mat4x4.hpp>

#include "shading/sampler.h"
#include "shading/techniques/classic.h"
#include "shading/techniques/light_depth.h"
#include "shading/techniques/moments.h"
#include "shading/techniques/technique.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// Everything a fragment needs to read a light's filtered map, copied once per draw.
struct FilteredReader {
  glm::mat4 shadow{1.0f};  // bias × proj × view
  glm::mat4 view{1.0f};    // the light's view (linear depth of perspective maps)
  LightDepth depth;
  LightKind kind = LightKind::directional;
  glm::vec3 position{0.0f}, direction{0.0f, -1.0f, 0.0f};
  BiasParams bias;  // constant, slope (in linear depth units) and normal offset; offset acts in the depth pass
  MomentParams params;
  Texture2D moments;  // view of the blurred moment target (R32F, RG32F or RGBA32F: moment_format), its mips
  Sampler sampler = Sampler::plain(Filter::linear, Wrap::clamp_to_edge);  // moment_sampler(params.mips)
};

// Where world point p with unit normal n reads the map and its linear depth there (bias applied); false where
// a spot light leaves it unlit (behind the light or outside its map), and for a directional map's outside,
// where `lit` is set instead.
bool filtered_context(const FilteredReader& r, glm::vec3 p, glm::vec3 n, glm::vec2& st, float& depth, bool& lit);

// Visibility in [0, 1] of a query's point: one lookup of the moments at the level of detail its screen
// derivatives give (moment_lod.h), the kind's formula.
float filtered_visibility(const FilteredReader& r, const ShadowQuery& q);
// The same for world point p with unit normal n and no derivatives (level 0).
float filtered_visibility(const FilteredReader& r, glm::vec3 p, glm::vec3 n);

// One pass of a built depth-map set turned filterable: the moment target (the pass's viewport, encoded then
// blurred on its own, so the slices of an atlas do not blur into each other), its blur scratch and a view (with
// the blurred map's mip chain unless MomentParams::mips is none).
struct MomentMap {
  std::unique_ptr<raster::ColorTarget> map, scratch;
  Texture2D view;
};

// Encodes pass `pass` of `set` (built) into `out` and blurs it; the targets are (re)made at the pass's size. The
// stored depth is made linear as the pass's projection asks (LightDepth::of), or as `depth` says (a cube
// face's radial distance is linear already).
raster::DrawStats filter_pass(raster::Renderer& renderer, const ShadowMapSet& set, size_t pass,
                              const MomentParams& params, int blur_radius, MomentMap& out);
raster::DrawStats filter_pass(raster::Renderer& renderer, const ShadowMapSet& set, size_t pass,
                              const LightDepth& depth, const MomentParams& params, int blur_radius, MomentMap& out);

// The `moments` parameter of the techniques that take one (cascades, cube): none, or the kind. Throws
// TechniqueError for a filter other than the default pcf, or pcf_taps, beside a kind: the moments are read with
// one bilinear lookup, so the filter would silently do nothing.
std::optional<MomentKind> moments_param(const ShadowConfig& config);

// A built classic map set (one pass) turned filterable: its moment map and the reader.
struct FilteredMap {
  MomentMap moments;
  FilteredReader reader;
};

// Runs the encode and blur passes over `set`'s (already built) depth map and sets up the reader.
raster::DrawStats filter_classic_map(raster::Renderer& renderer, const ShadowMapSet& set, const ClassicLight& light,
                                     const BiasParams& bias, const MomentParams& params, int blur_radius,
                                     FilteredMap& out);

// The moment kind and its parameters from a ShadowConfig whose technique is esm, vsm, evsm2 or evsm4.
MomentParams moment_params(const ShadowConfig& config);
// The parameters of moment kind `kind` from a ShadowConfig whose technique lists them (cascades' moments).
MomentParams moment_params(MomentKind kind, const ShadowConfig& config);

// The registry's factories (technique.h), one per kind; the map is planned as the classic one.
std::unique_ptr<LightShadow> plan_esm(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_vsm(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_evsm2(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_evsm4(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
