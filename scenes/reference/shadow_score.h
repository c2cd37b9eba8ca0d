// A technique's shadow scored against the exact one, light by light, over the lit-facing pixels: those whose
// technique was asked (SurfaceRecord::lit_facing) and that the reference's light reaches (ExactVisibility::
// reached). The others are unlit for the exact test whatever the technique does, and counted apart (`unreached`),
// not scored: the terminator of a tessellated curve, where the smooth shading normal faces the light and the flat
// triangle does not, and the back half-space of a hemispherical light, which the shading lights as a point light.
// A pixel is in shadow for the technique when its factor S is below 0.5. False-shadowed: S < 0.5 where the ray
// reached the light unblocked (acne, over-darkening); false-lit: S >= 0.5 where it was blocked (leaks,
// peter-panning). Each is split into pixels near a boundary of the exact image and
// elsewhere: a boundary pixel has a 4-neighbour whose exact lighting (reached and unoccluded) differs, or whose
// geometric normal turns by more than 30° (a crease or a contact between two surfaces); "near" is within
// `near_radius` pixels of one (Chebyshev distance).
#pragma once
#include <cstdint>
#include <vector>

#include "scenes/frame/surface_record.h"
#include "scenes/reference/exact_visibility.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

struct ScoreOptions {
  float shadow_below = 0.5f;  // S below this counts as shadow
  int near_radius = 2;        // pixels
};

struct LightScore {
  size_t scored = 0;      // lit-facing pixels
  size_t unreached = 0;   // asked, but the exact light does not reach them: not scored
  size_t false_shadowed_near = 0, false_shadowed_elsewhere = 0;
  size_t false_lit_near = 0, false_lit_elsewhere = 0;
  double mean_abs_error = 0.0;  // mean |S − V| over the scored pixels (V: 1 visible, 0 not)
  // Connected (8-neighbour) groups of false-lit pixels: the largest's pixel count, and the longest side of any
  // group's bounding box (how long a leak runs).
  size_t largest_false_lit_group = 0;
  int longest_false_lit_run = 0;

  size_t false_shadowed() const { return false_shadowed_near + false_shadowed_elsewhere; }
  size_t false_lit() const { return false_lit_near + false_lit_elsewhere; }
  // n as a percentage of the scored pixels (0 when none were scored).
  double percent(size_t n) const { return scored ? 100.0 * double(n) / double(scored) : 0.0; }
};

// Per pixel, for the error map: bit 0 false-shadowed, bit 1 false-lit, for any light.
enum ErrorBits : uint8_t { kFalseShadowed = 1, kFalseLit = 2 };

struct FrameScore {
  std::vector<LightScore> lights;
  std::vector<uint8_t> errors;  // ErrorBits per pixel, GL row order
};

// Throws ReferenceError when the record and the reference differ in size or light count.
FrameScore score_frame(const frame::SurfaceRecord& technique, const ExactVisibility& exact,
                       const ScoreOptions& options = {});

// Boundary pixels of the exact image for one light, and their neighbourhood within `radius` (exposed for tests).
std::vector<uint8_t> exact_boundaries(const frame::SurfaceRecord& record, const ExactVisibility& exact, size_t light);
std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, int width, int height, int radius);

SHADOWLAB_ISA_END
}  // namespace reference
