// The depth test and depth write on eight pixels at a time, per depth format: converting the fragment depth to
// the stored representation (CONVENTIONS), comparing with one of GL's eight functions, and writing under a mask.
#pragma once
#include <cstdint>

#include "raster/formats.h"
#include "raster/simd/vec.h"
#include "raster/state.h"

namespace raster {

template <DepthFormat F>
struct DepthTraits;

// Unorm formats compare integer codes: code = round(z · max) of the clamped depth.
template <>
struct DepthTraits<DepthFormat::d16> {
  using Storage = uint16_t;
  using Value = simd::VecI32;
  static Value from_depth(simd::VecF32 z) { return simd::round_to_int(z * simd::VecF32::splat(65535.0f)); }
  static Value load(const Storage* p) { return Value::load_u16(p); }
  static void store(Storage* p, Value v) { v.store_u16(p); }
};

template <>
struct DepthTraits<DepthFormat::d24> {
  using Storage = uint32_t;
  using Value = simd::VecI32;
  static Value from_depth(simd::VecF32 z) { return simd::round_to_int(z * simd::VecF32::splat(16777215.0f)); }
  static Value load(const Storage* p) { return Value::load_u32(p); }
  static void store(Storage* p, Value v) { v.store_u32(p); }
};

// d32f compares the clamped float itself.
template <>
struct DepthTraits<DepthFormat::d32f> {
  using Storage = float;
  using Value = simd::VecF32;
  static Value from_depth(simd::VecF32 z) { return z; }
  static Value load(const Storage* p) { return Value::load(p); }
  static void store(Storage* p, Value v) { v.store(p); }
};

// Lanes where `frag FUNC stored` holds.
template <DepthFunc Func, class Value>
inline simd::Mask depth_compare(Value frag, Value stored) {
  using simd::Mask;
  if constexpr (Func == DepthFunc::never) return Mask::from_bits(0);
  if constexpr (Func == DepthFunc::always) return Mask::all();
  if constexpr (Func == DepthFunc::less) return simd::cmp_lt(frag, stored);
  if constexpr (Func == DepthFunc::greater) return simd::cmp_lt(stored, frag);
  if constexpr (Func == DepthFunc::equal) return simd::cmp_eq(frag, stored);
  if constexpr (Func == DepthFunc::notequal) return simd::cmp_neq(frag, stored);
  if constexpr (Func == DepthFunc::lequal) return simd::cmp_le(frag, stored);
  if constexpr (Func == DepthFunc::gequal) return simd::cmp_le(stored, frag);
}

// Calls f.template operator()<Func>() with the compile-time depth function matching `func`: the draw-level
// dispatch that keeps the per-pixel loop free of run-time choices.
template <class F>
decltype(auto) dispatch_depth_func(DepthFunc func, F&& f) {
  switch (func) {
    case DepthFunc::never: return f.template operator()<DepthFunc::never>();
    case DepthFunc::less: return f.template operator()<DepthFunc::less>();
    case DepthFunc::equal: return f.template operator()<DepthFunc::equal>();
    case DepthFunc::lequal: return f.template operator()<DepthFunc::lequal>();
    case DepthFunc::greater: return f.template operator()<DepthFunc::greater>();
    case DepthFunc::notequal: return f.template operator()<DepthFunc::notequal>();
    case DepthFunc::gequal: return f.template operator()<DepthFunc::gequal>();
    case DepthFunc::always: break;
  }
  return f.template operator()<DepthFunc::always>();
}

template <class F>
decltype(auto) dispatch_depth_format(DepthFormat format, F&& f) {
  switch (format) {
    case DepthFormat::d16: return f.template operator()<DepthFormat::d16>();
    case DepthFormat::d24: return f.template operator()<DepthFormat::d24>();
    case DepthFormat::d32f: break;
  }
  return f.template operator()<DepthFormat::d32f>();
}

}  // namespace raster
