// Reading an omnidirectional light's map in the camera pass: omni_visibility takes a batch of points (a quad)
// and makes its run-time choices — the technique (cube, paraboloid, pyramid) and the filter — once for the
// batch, then runs the compile-time visibility function of that pair per point. Also the three techniques'
// registry factories (omni_technique.cpp).
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "shading/techniques/cube_map.h"
#include "shading/techniques/paraboloid.h"
#include "shading/techniques/pyramid.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

inline void omni_visibility(const OmniReader& r, std::span<const ShadowQuery> q, std::span<float> vis) {
  dispatch_filter(r.filter_kind, r.filter.pcf_taps, [&]<class F, bool kPcf>() {
    switch (r.kind) {
      case OmniKind::cube:
        for (size_t i = 0; i < q.size(); ++i) vis[i] = cube_visibility<F, kPcf>(r, q[i].p, q[i].n, q[i].frag);
        return;
      case OmniKind::paraboloid:
        for (size_t i = 0; i < q.size(); ++i) vis[i] = paraboloid_visibility<F, kPcf>(r, q[i].p, q[i].n, q[i].frag);
        return;
      case OmniKind::pyramid:
        for (size_t i = 0; i < q.size(); ++i) vis[i] = pyramid_visibility<F, kPcf>(r, q[i].p, q[i].n, q[i].frag);
        return;
    }
  });
}

// The registry's factories. Parameters: cube `seamless`; paraboloid `paraboloid_pack`, `split_plane`. Throw
// TechniqueError for a zero range or direction, the `offset` bias (the distance is written per fragment, so no
// polygon offset applies), an odd pyramid side or a bad split plane.
std::unique_ptr<LightShadow> plan_cube(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_paraboloid(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
std::unique_ptr<LightShadow> plan_pyramid(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);

// "x", "-y", ... or "a,b,c": a paraboloid split plane's normal; none when the text is neither.
std::optional<glm::vec3> parse_split_plane(const std::string& text);

SHADOWLAB_ISA_END
}  // namespace shading::tech
