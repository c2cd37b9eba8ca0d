// How the camera pass reads a blurred moment map's mip chain: the sampler of the `moment_mips` setting, and the
// level of detail a GPU's texture() would derive for the lookup, from the map coordinates of the point and of its
// quad's neighbours one pixel right and one pixel up (the query's coarse screen derivatives, ShadowQuery). The
// moments are linear in what they average, so a coarser level is the blurred map filtered further, not a
// different map: a minified receiver reads the mean moments of its footprint instead of aliasing.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/lod.h"
#include "shading/lookup.h"
#include "shading/sampler.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// LINEAR within a level, clamped to the edge, with the given mip filter (MipFilter::none: level 0 alone).
inline Sampler moment_sampler(MipFilter mips) { return Sampler::plain(Filter::linear, Wrap::clamp_to_edge, mips); }

// One lookup of the moments at st. `st_of` maps a world point to the map's coordinates; its differences between
// q + dpdx, q + dpdy and q (q: the query's point as the map is read, e.g. after a normal offset) are the quad's
// coarse derivatives of st, and λ_base = log2 of the longer of the two in texels (lod_from_gradients, GL's
// isotropic rule). Without mips, or with zero derivatives, the lookup is level 0's bilinear one.
template <class StOf>
inline glm::vec4 read_moments(const Texture2D& t, const Sampler& s, glm::vec2 st, glm::vec3 q, const ShadowQuery& sq,
                              StOf&& st_of) {
  float lambda = 0.0f;
  if (t.levels() > 1 && s.mip_filter != MipFilter::none) {
    const glm::vec2 s0 = st_of(q);
    const glm::vec2 dx = st_of(q + sq.dpdx) - s0, dy = st_of(q + sq.dpdy) - s0;
    lambda = lod_from_gradients(dx, dy, t.level(0).fwidth, t.level(0).fheight);
  }
  return texture_at(t, s, st, lambda);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
