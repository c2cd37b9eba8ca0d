// Reading an omnidirectional light's map in the camera pass: omni_visibility takes a batch of points (a quad)
// and makes its run-time choices — the technique (cube, paraboloid, pyramid) and the filter — once for the
// batch, then runs the compile-time visibility function of that pair per point.
#pragma once
#include <span>

#include "shading/techniques/cube_map.h"
#include "shading/techniques/paraboloid.h"
#include "shading/techniques/pyramid.h"

namespace shading::tech {

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

}  // namespace shading::tech
