// Percentage-closer soft shadows (Fernando 2005) for directional and spot lights on the classic technique's
// single depth map: a blocker search over the region of the map from which the light's area can be hidden,
// the penumbra estimated from the mean blocker depth by similar triangles, then a Poisson-disc PCF (16
// hardware 2×2 PCF taps, the disc turned per pixel) with that kernel. A point whose search finds no blocker
// is lit at once (early exit). The light's size: a directional light's angular diameter, a spot light's radius.
#pragma once
#include <memory>
#include <span>

#include <glm/vec2.hpp>

#include "shading/techniques/classic.h"
#include "shading/techniques/light_depth.h"
#include "shading/techniques/technique.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

struct PcssReader {
  ClassicReader classic;  // matrices, bias, the hardware PCF lookup of the filter taps
  Texture2D map;          // the depth map, read texel by texel by the blocker search
  LightDepth depth;       // spot: window depth → view distance
  float tan_half = 0.0f;  // directional: tan(angular diameter / 2)
  float range = 1.0f;     // directional: metres per unit of window depth
  float radius = 0.0f;    // spot: the light's radius in metres
  float near = 0.1f;      // spot: view distance of the near plane
  glm::vec2 scale{1.0f};  // directional: map coordinates per metre; spot: the projection's P00, P11
  glm::vec2 texel{1.0f};  // one texel in map coordinates: the smallest filter radius
  glm::mat4 unshadow{1.0f};  // inverse of classic.shadow: map (s, t, window depth) back to the world
};

// The window depth gradient, per unit of map coordinates, of the receiver's tangent plane through p (normal n)
// as the map sees it around st (where p projects, window depth z): each tap compares the blockers with the
// plane's own depth there (receiver-plane depth bias), so a wide kernel on a surface tilted to the light does
// not compare the surface with itself. Clamped to 0.01 per texel (grazing planes).
glm::vec2 receiver_gradient(const PcssReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 st, float z);

// The reader over pass `pass` of a built map set (the classic map's one pass, or a cascade's slice); `size` is
// the light's angular diameter in degrees (directional) or its radius in metres (spot). Every conversion to map
// coordinates (metres per unit of depth, map coordinates per metre, one texel) comes from that pass's own
// projection and viewport, so slices of different texel sizes give the same penumbra in metres.
PcssReader make_pcss_reader(const ShadowMapSet& set, const ClassicLight& light, const ClassicSettings& settings,
                            float size, size_t pass = 0);

// The search region's radius in map coordinates for a receiver at window depth ref: directional, the light's
// cone between the map's near plane and the receiver; spot, the light's disc seen from the receiver, cut at the
// near plane or a quarter of the receiver's distance, whichever is farther.
glm::vec2 pcss_search_radius(const PcssReader& r, float ref);

// The filter kernel's radius in map coordinates (half the penumbra width) for a receiver at window depth ref
// and a mean blocker depth `blocker`: directional (z_r − z_b) · tan(θ/2); spot R · (z_r − z_b) / z_b at the
// receiver; never below one texel.
glm::vec2 pcss_filter_radius(const PcssReader& r, float ref, float blocker);

// Visibility in [0, 1] of world point p with unit normal n, seen at window position frag (the disc's turn).
float pcss_visibility(const PcssReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag);

std::unique_ptr<LightShadow> plan_pcss(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

SHADOWLAB_ISA_END
}  // namespace shading::tech
