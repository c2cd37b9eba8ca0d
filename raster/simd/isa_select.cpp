// The instruction-set choice of isa_select.h, from CPUID and XGETBV.
#include "raster/simd/isa_select.h"

#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace raster::simd {

// Read from CPUID rather than __builtin_cpu_supports, which GCC and clang do not both know for LZCNT and F16C; the
// XCR0 test keeps a hypervisor's AVX2 that the guest cannot use from being taken.
bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (__get_cpuid_max(0, nullptr) < 7) return false;
  __cpuid_count(1, 0, a, b, c, d);
  const bool fma = c & (1u << 12), osxsave = c & (1u << 27), avx = c & (1u << 28), f16c = c & (1u << 29);
  if (!(fma && osxsave && avx && f16c)) return false;
  unsigned xcr0_lo = 0, xcr0_hi = 0;
  __asm__ volatile("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0));
  if ((xcr0_lo & 0x6u) != 0x6u) return false;
  __cpuid_count(7, 0, a, b, c, d);
  const bool bmi1 = b & (1u << 3), avx2 = b & (1u << 5), bmi2 = b & (1u << 8);
  if (!(bmi1 && avx2 && bmi2)) return false;
  if (__get_cpuid_max(0x80000000u, nullptr) < 0x80000001u) return false;
  __cpuid_count(0x80000001u, 0, a, b, c, d);
  return c & (1u << 5);  // LZCNT (ABM)
#else
  return false;
#endif
}

bool cpu_has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
  if (!cpu_has_avx2()) return false;
  unsigned a = 0, b = 0, c = 0, d = 0;
  unsigned xcr0_lo = 0, xcr0_hi = 0;
  __asm__ volatile("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0));
  if ((xcr0_lo & 0xE6u) != 0xE6u) return false;  // XMM, YMM, opmask, ZMM_Hi256, Hi16_ZMM
  __cpuid_count(7, 0, a, b, c, d);
  const bool f = b & (1u << 16), dq = b & (1u << 17), bw = b & (1u << 30), vl = b & (1u << 31);
  return f && dq && bw && vl;
#else
  return false;
#endif
}

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::avx512: return "avx512";
    case Isa::avx2: return "avx2";
    case Isa::scalar: break;
  }
  return "scalar";
}

std::optional<Isa> select_isa(const char* forced, BuiltIsas built, std::string& error) {
  if (forced != nullptr && *forced == '\0') forced = nullptr;
  const bool want_auto = forced == nullptr || std::strcmp(forced, "auto") == 0;
  struct Candidate {
    Isa isa;
    bool built;
    bool (*cpu_has)();  // null: any CPU
    const char* cpu_lacks;
    const char* build_lacks;
  };
  // Widest first, as auto takes them.
  const Candidate candidates[] = {
      {Isa::avx512, built.avx512, cpu_has_avx512, "this CPU lacks AVX-512 F, DQ, BW or VL (or AVX2)", "AVX-512"},
      {Isa::avx2, built.avx2, cpu_has_avx2, "this CPU lacks AVX2, FMA, BMI1/2, LZCNT or F16C", "AVX2"},
      {Isa::scalar, built.scalar, nullptr, "", "scalar"},
  };
  for (const Candidate& c : candidates) {
    if (!want_auto && std::strcmp(forced, isa_name(c.isa)) != 0) continue;
    if (c.built && (c.cpu_has == nullptr || c.cpu_has())) return c.isa;
    if (want_auto) continue;
    error = std::string(isa_name(c.isa)) + " was asked for, but " +
            (c.built ? c.cpu_lacks : "this build has no " + std::string(c.build_lacks) + " path (SHADOWLAB_ISAS)");
    return std::nullopt;
  }
  error = want_auto ? "this CPU lacks the instruction sets this build has (SHADOWLAB_ISAS)"
                    : "unknown instruction set (expected avx512, avx2, scalar or auto)";
  return std::nullopt;
}

}  // namespace raster::simd
