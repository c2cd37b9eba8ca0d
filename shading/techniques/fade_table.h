// The projective article's second enhancement: "the alpha of the shadowing pass from a texture lookup from the
// distance to the light". A fade table is a 1-D texture (N × 1, R32F) indexed by the receiver's distance behind
// the caster, normalised over [fade_start, fade_end] to t in [0, 1]; the receiver pass reads it with GL's
// LINEAR filter and clamps at the ends. The user gives strengths (1: the full shadow, 0: none); the texels hold
// 1 − strength, the amount by which the shadow has faded, which is what the receiver pass mixes towards white
// with (factor = mask + (1 − mask) · fade): with the two-texel table (1, 0) that is exactly the formula's linear
// ramp, bit for bit (fade_at below).
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The most texels a table may have (a 1-D texture of the time: 256 entries).
inline constexpr int kMaxFadeTexels = 256;
// Texels of the `smoothstep` table: 1 − smoothstep(0, 1, t) sampled at t = i / 255.
inline constexpr int kSmoothstepTexels = 256;

// A table as written in a scene's `fade_table` or --fade-table: `linear` (1, 0: the formula's ramp),
// `smoothstep` (kSmoothstepTexels strengths of 1 − smoothstep(0, 1, t): a shadow that starts and ends its fade
// gently), or 2 to kMaxFadeTexels comma-separated strengths in [0, 1], the first at fade_start and the last at
// fade_end, evenly spaced. Nullopt with `why` set when the text is none of these.
std::optional<std::vector<float>> parse_fade_table(std::string_view text, std::string& why);

// The texture of a table of strengths (2 to kMaxFadeTexels of them): N × 1 R32F texels of 1 − strength.
Texture2D make_fade_texture(std::span<const float> strengths);

// The fade at t in [0, 1] (clamped): GL's LINEAR filter on the table, clamp to edge, with the coordinate given
// in texels, u = t · (N − 1), so texel 0 is read alone at t = 0 and texel N − 1 at t = 1 (a GPU gets there with
// s = (u + 0.5) / N, up to the rounding of that division). v0 + frac · (v1 − v0), as filter.h's lerp.
float fade_at(const Texture2D& table, float t);

SHADOWLAB_ISA_END
}  // namespace shading::tech
