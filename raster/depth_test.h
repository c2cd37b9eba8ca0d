// The depth test and depth write on eight pixels at a time (sixteen, two rows, for the depth-only back end), per
// depth format: converting the fragment depth to the stored representation (CONVENTIONS), comparing with one of
// GL's eight functions (fixed at compile time, or chosen at run time once per draw), and writing under a mask.
#pragma once
#include <cstdint>
#include <type_traits>

#include "raster/formats.h"
#include "raster/simd/vec.h"
#include "raster/state.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

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
  // Two rows: lanes 0–7 at r0, 8–15 at r1.
  static simd::VecI32x16 from_depth(simd::VecF32x16 z) {
    return simd::round_to_int(z * simd::VecF32x16::splat(65535.0f));
  }
  static simd::VecI32x16 load_rows(const Storage* r0, const Storage* r1) {
    return simd::VecI32x16::load_rows_u16(r0, r1);
  }
  static void store_rows(Storage* r0, Storage* r1, simd::VecI32x16 v) { v.store_rows_u16(r0, r1); }
};

template <>
struct DepthTraits<DepthFormat::d24> {
  using Storage = uint32_t;
  using Value = simd::VecI32;
  static Value from_depth(simd::VecF32 z) { return simd::round_to_int(z * simd::VecF32::splat(16777215.0f)); }
  static Value load(const Storage* p) { return Value::load_u32(p); }
  static void store(Storage* p, Value v) { v.store_u32(p); }
  static simd::VecI32x16 from_depth(simd::VecF32x16 z) {
    return simd::round_to_int(z * simd::VecF32x16::splat(16777215.0f));
  }
  static simd::VecI32x16 load_rows(const Storage* r0, const Storage* r1) {
    return simd::VecI32x16::load_rows_u32(r0, r1);
  }
  static void store_rows(Storage* r0, Storage* r1, simd::VecI32x16 v) { v.store_rows_u32(r0, r1); }
};

// d32f compares the clamped float itself.
template <>
struct DepthTraits<DepthFormat::d32f> {
  using Storage = float;
  using Value = simd::VecF32;
  static Value from_depth(simd::VecF32 z) { return z; }
  static Value load(const Storage* p) { return Value::load(p); }
  static void store(Storage* p, Value v) { v.store(p); }
  static simd::VecF32x16 from_depth(simd::VecF32x16 z) { return z; }
  static simd::VecF32x16 load_rows(const Storage* r0, const Storage* r1) { return simd::VecF32x16::load_rows(r0, r1); }
  static void store_rows(Storage* r0, Storage* r1, simd::VecF32x16 v) { v.store_rows(r0, r1); }
};

// The mask type of a comparison of two Values (simd::Mask for eight lanes, simd::Mask16 for sixteen).
template <class Value>
using MaskOf = decltype(simd::cmp_eq(Value{}, Value{}));

// Lanes where `frag FUNC stored` holds, the function fixed at compile time. GL's NaN rule on d32f: every
// comparison is false with a NaN operand, except NOTEQUAL, which is true.
template <DepthFunc Func, class Value>
inline MaskOf<Value> depth_compare(Value frag, Value stored) {
  using Mask = MaskOf<Value>;
  if constexpr (Func == DepthFunc::never) return Mask::from_bits(0);
  if constexpr (Func == DepthFunc::always) return Mask::from_bits(0xFFFFu);
  if constexpr (Func == DepthFunc::less) return simd::cmp_lt(frag, stored);
  if constexpr (Func == DepthFunc::greater) return simd::cmp_lt(stored, frag);
  if constexpr (Func == DepthFunc::equal) return simd::cmp_eq(frag, stored);
  if constexpr (Func == DepthFunc::notequal) return simd::cmp_neq(frag, stored);
  if constexpr (Func == DepthFunc::lequal) return simd::cmp_le(frag, stored);
  if constexpr (Func == DepthFunc::gequal) return simd::cmp_le(stored, frag);
}

// The depth test as a stage holds it: one function fixed at compile time, for the hot paths that specialise on it.
template <DepthFunc Func>
struct FixedDepthFunc {
  template <class Value>
  MaskOf<Value> operator()(Value frag, Value stored) const { return depth_compare<Func>(frag, stored); }
};

// The depth test with the function chosen at run time, once per draw, without a branch per pixel: a comparison
// falls in one of four classes (frag < stored, ==, >, or unordered: a NaN on d32f), and each function is the
// set of classes it passes, one bit each. The SIMD form computes three comparisons and keeps the classes the
// function's masks select; NOTEQUAL and ALWAYS are the only functions that pass the unordered class, and both
// pass < and > too, so "not equal" stands for "< or > or unordered" where the unordered bit is set.
class DepthCompare {
 public:
  static constexpr unsigned kLess = 1, kEqual = 2, kGreater = 4, kUnordered = 8;
  static constexpr unsigned classes(DepthFunc f) {
    switch (f) {
      case DepthFunc::never: return 0;
      case DepthFunc::less: return kLess;
      case DepthFunc::equal: return kEqual;
      case DepthFunc::lequal: return kLess | kEqual;
      case DepthFunc::greater: return kGreater;
      case DepthFunc::notequal: return kLess | kGreater | kUnordered;
      case DepthFunc::gequal: return kGreater | kEqual;
      case DepthFunc::always: break;
    }
    return kLess | kEqual | kGreater | kUnordered;
  }

  explicit DepthCompare(DepthFunc f)
      : bits_(classes(f)),
        less_(lanes(kLess)),
        equal_(lanes(kEqual)),
        greater_(lanes(kGreater)),
        unordered_(lanes(kUnordered)) {}

  // Lanes where `frag FUNC stored` holds (VecI32 / VecI32x16 for the unorm formats, VecF32 / VecF32x16 for d32f).
  template <class Value>
  MaskOf<Value> operator()(Value frag, Value stored) const {
    using Mask = MaskOf<Value>;
    const Mask eq = simd::cmp_eq(frag, stored);
    return (simd::cmp_lt(frag, stored) & wide<Mask>(less_)) | (simd::cmp_lt(stored, frag) & wide<Mask>(greater_)) |
           (eq & wide<Mask>(equal_)) | and_not(wide<Mask>(unordered_), eq);
  }
  // One pixel (int32_t codes or floats), the same classes.
  template <class T>
  bool test(T frag, T stored) const {
    const unsigned c = frag < stored ? kLess : frag == stored ? kEqual : frag > stored ? kGreater : kUnordered;
    return (bits_ & c) != 0;
  }

 private:
  simd::Mask lanes(unsigned c) const { return simd::Mask::from_bits((bits_ & c) ? 0xFFu : 0u); }
  // A class's eight-lane mask as the comparison's mask type: both rows the same.
  template <class Mask>
  static Mask wide(simd::Mask m) {
    if constexpr (std::is_same_v<Mask, simd::Mask>) return m;
    else return Mask::rows(m, m);
  }
  unsigned bits_;
  simd::Mask less_, equal_, greater_, unordered_;
};

// Calls f(compare) with the depth test a depth-only draw runs: LESS and LEQUAL, the functions of shadow and depth
// pre-passes, fixed at compile time (they use hierarchical depth, depth_stage.h); every other function through
// the one run-time DepthCompare.
template <class F>
decltype(auto) dispatch_depth_only_func(DepthFunc func, F&& f) {
  switch (func) {
    case DepthFunc::less: return f(FixedDepthFunc<DepthFunc::less>{});
    case DepthFunc::lequal: return f(FixedDepthFunc<DepthFunc::lequal>{});
    default: break;
  }
  return f(DepthCompare(func));
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

SHADOWLAB_ISA_END
}  // namespace raster
