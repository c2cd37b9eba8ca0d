// The filters of shadow_filters.h over up to eight points at once (a fragment_pair's live lanes): a filter of one
// tap is one eight-lane lookup through a kernel of ShadowLookup2D::visit (PcfKernel or GenericShadowKernel), a
// filter of several takes its taps two at a time as one sixteen-lane lookup in AVX-512 builds (eight at a time,
// as four such lookups run side by side, where the filter has that many), one at a time elsewhere
// (for_each_tap); the taps are summed per lane in the scalar filter's order with the same float operations, so
// lane l equals the scalar filter on point l bit for bit. Per-lane tap offsets (stratified, rotated) are
// computed per lane by the scalar code.
#pragma once
#include <array>
#include <type_traits>

#include "raster/simd/vec.h"
#include "shading/shadow_lookup.h"
#include "shading/techniques/shadow_filters.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// Up to eight sample contexts, also as lanes (s, t, ref). Lanes past `count` repeat lane 0: they are looked up
// and their results ignored.
struct SampleLanes {
  std::array<SampleContext, 8> ctx;
  int count = 0;
  raster::simd::VecF32 s, t, ref;

  // Pads the unused lanes and builds the coordinate lanes; call once after the contexts are filled.
  void finish() {
    alignas(32) float ps[8], pt[8], pr[8];
    for (int l = 0; l < 8; ++l) {
      if (l >= count) ctx[size_t(l)] = ctx[0];
      ps[l] = ctx[size_t(l)].st.x, pt[l] = ctx[size_t(l)].st.y, pr[l] = ctx[size_t(l)].ref;
    }
    s = raster::simd::VecF32::load(ps), t = raster::simd::VecF32::load(pt), ref = raster::simd::VecF32::load(pr);
  }
};

namespace lanes_detail {
using raster::simd::VecF32;
using raster::simd::VecF32x16;

// One tap per lane at (s + ox, t + oy, ref): Taps' `c.st + offset` as a lane add.
template <class K>
VecF32 tap(const K& k, const SampleLanes& b, VecF32 ox, VecF32 oy) {
  return k(b.s + ox, b.t + oy, b.ref);
}
// The same offset for every lane: the scalar `d * spread` splatted.
template <class K>
VecF32 tap(const K& k, const SampleLanes& b, glm::vec2 off) {
  return tap(k, b, VecF32::splat(off.x), VecF32::splat(off.y));
}
// Looks up taps 0 .. n − 1 (n even) on every lane, tap i at the lane offsets off(i, ox, oy), and hands each tap's
// result to add(VecF32) in tap order: two taps per sixteen-lane lookup, those handed over
// detail::kLookupsPerBatch at a time while enough taps are left, or one tap per eight-lane lookup
// (detail::kTapsPerLookup says which pays on this instruction set).
template <class K, class Off, class Add>
void for_each_tap(const K& k, const SampleLanes& b, int n, Off&& off, Add&& add) {
  if constexpr (shading::detail::kTapsPerLookup == 2) {
    constexpr int kBatch = shading::detail::kLookupsPerBatch;
    int i = 0;
    if constexpr (kBatch > 1) {
      for (; i + 2 * kBatch <= n; i += 2 * kBatch) {
        std::array<VecF32x16, kBatch> s, t, ref, r;
        for (int j = 0; j < kBatch; ++j) {
          VecF32 ox0, oy0, ox1, oy1;
          off(i + 2 * j, ox0, oy0), off(i + 2 * j + 1, ox1, oy1);
          s[size_t(j)] = VecF32x16::rows(b.s + ox0, b.s + ox1), t[size_t(j)] = VecF32x16::rows(b.t + oy0, b.t + oy1);
          ref[size_t(j)] = VecF32x16::rows(b.ref, b.ref);
        }
        k(s, t, ref, r);
        for (const VecF32x16& v : r) add(v.row0()), add(v.row1());
      }
    }
    for (; i < n; i += 2) {
      VecF32 ox0, oy0, ox1, oy1;
      off(i, ox0, oy0), off(i + 1, ox1, oy1);
      const VecF32x16 r =
          k(VecF32x16::rows(b.s + ox0, b.s + ox1), VecF32x16::rows(b.t + oy0, b.t + oy1), VecF32x16::rows(b.ref, b.ref));
      add(r.row0()), add(r.row1());
    }
  } else {
    for (int i = 0; i < n; ++i) {
      VecF32 ox, oy;
      off(i, ox, oy);
      add(tap(k, b, ox, oy));
    }
  }
}
// Offsets for for_each_tap: tap i at d(i) · spread on every lane.
inline auto splat_offsets(auto&& d, float spread) {
  return [d, spread](int i, VecF32& ox, VecF32& oy) {
    const glm::vec2 off = d(i) * spread;
    ox = VecF32::splat(off.x), oy = VecF32::splat(off.y);
  };
}

template <PoissonMode kMode, class K>
VecF32 poisson(const K& k, const SampleLanes& b, const FilterParams& p, int n) {
  std::array<PoissonTaps<kMode>, 8> at;
  if constexpr (kMode != PoissonMode::fixed)
    for (size_t l = 0; l < 8; ++l) at[l] = PoissonTaps<kMode>(b.ctx[l], p);
  // Tap i's offsets on every lane: one for all (fixed), or each lane's own.
  const auto offsets = [&](int i, VecF32& ox, VecF32& oy) {
    if constexpr (kMode == PoissonMode::fixed) {
      const glm::vec2 off = at[0].disc(i) * p.spread;
      ox = VecF32::splat(off.x), oy = VecF32::splat(off.y);
    } else {
      alignas(32) float x[8], y[8];
      for (size_t l = 0; l < 8; ++l) {
        const glm::vec2 off = at[l].disc(i) * p.spread;
        x[l] = off.x, y[l] = off.y;
      }
      ox = VecF32::load(x), oy = VecF32::load(y);
    }
  };
  if (p.tutorial) {  // tutorial_step and tutorial_visibility per lane
    const VecF32 one = VecF32::splat(1.0f), weight = VecF32::splat(kTutorialTapWeight);
    VecF32 visibility = one;
    for_each_tap(k, b, n, offsets, [&](VecF32 v) { visibility = visibility - weight * (one - v); });
    return raster::simd::max(visibility, VecF32::splat(0.0f));
  }
  VecF32 sum = VecF32::splat(0.0f);
  for_each_tap(k, b, n, offsets, [&](VecF32 v) { sum = sum + v; });
  return raster::simd::div(sum, VecF32::splat(float(n)));
}
}  // namespace lanes_detail

// The batch form of Filter (one of shadow_filters.h's) with kernel k: lane l is Filter on b.ctx[l].
template <class Filter, class K>
raster::simd::VecF32 filter_lanes(const K& k, const SampleLanes& b, const FilterParams& p) {
  using lanes_detail::tap;
  using raster::simd::VecF32;
  if constexpr (std::is_same_v<Filter, HardFilter> || std::is_same_v<Filter, PcfFilter>) {
    return tap(k, b, glm::vec2(0.0f));
  } else if constexpr (std::is_same_v<Filter, EarlyBailFilter>) {
    using lanes_detail::for_each_tap;
    using lanes_detail::splat_offsets;
    static_assert(kOuterTaps.size() % 2 == 0 && kPoissonDisk.size() % 2 == 0);
    VecF32 outer = VecF32::splat(0.0f);
    for_each_tap(k, b, int(kOuterTaps.size()),
                 splat_offsets([](int i) { return kPoissonDisk[size_t(kOuterTaps[size_t(i)])]; }, p.spread),
                 [&](VecF32 v) { outer = outer + v; });
    alignas(32) float o[8];
    outer.store(o);
    bool full = false;  // some lane whose outer taps disagree
    for (int l = 0; l < b.count; ++l) full |= !(o[l] == 0.0f || o[l] == 4.0f);
    const VecF32 bail = outer * VecF32::splat(0.25f);
    if (!full) return bail;
    VecF32 sum = VecF32::splat(0.0f);
    for_each_tap(k, b, int(kPoissonDisk.size()), splat_offsets([](int i) { return kPoissonDisk[size_t(i)]; }, p.spread),
                 [&](VecF32 v) { sum = sum + v; });
    const VecF32 all = raster::simd::div(sum, VecF32::splat(16.0f));
    alignas(32) float r[8], a[8];
    bail.store(r), all.store(a);
    for (int l = 0; l < 8; ++l)
      if (!(o[l] == 0.0f || o[l] == 4.0f)) r[l] = a[l];
    return VecF32::load(r);
  } else {
    return lanes_detail::poisson<Filter::kMode>(k, b, p, p.taps >= 16 ? 16 : 4);
  }
}

// filter_lanes with the lookup the scalar filter would use (Taps<kPcf>; PcfFilter always the LINEAR one), its
// path chosen once here: the kernel of the LINEAR lookup's path, or the generic lookups for NEAREST.
template <class Filter, bool kPcf>
raster::simd::VecF32 filter_lanes(const MapLookups& maps, const SampleLanes& b, const FilterParams& p) {
  if constexpr (kPcf || std::is_same_v<Filter, PcfFilter>) {
    return maps.linear.visit([&](const auto& k) { return filter_lanes<Filter>(k, b, p); });
  } else {
    const GenericShadowKernel k{&maps.nearest.texture(), maps.nearest.sampler()};
    return filter_lanes<Filter>(k, b, p);
  }
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
