// shadowlab's entry point: picks the instruction set the pipeline runs on, once, before anything else, and hands
// the command line to that build of it (cli/run.cpp, compiled once per set in SHADOWLAB_ISAS: see
// raster/simd/isa.h). The widest set the CPU and the operating system support is taken; the environment
// variable SHADOWLAB_ISA=avx512|avx2|scalar|auto forces one. Every set gives bit-identical output
// (tests/cli/isa_dispatch_test.cpp), so the choice changes only the speed. This file is built for plain x86-64
// whatever the sets are: it must run on any CPU to tell it apart.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

// One declaration per set built (CMake defines SHADOWLAB_HAVE_ISA_<SET>); the definitions are cli/run.cpp's
// `cli::run` in the set's namespace.
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
namespace cli::isa_avx512 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
namespace cli::isa_avx2 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
namespace cli::isa_scalar {
int run(int argc, char** argv);
}
#endif

namespace {

constexpr int kExitBadInput = 2;

// Everything raster/simd/isa.h's AVX2 target enables, read from CPUID (GCC's and clang's
// __builtin_cpu_supports do not all know LZCNT and F16C): AVX2, FMA, BMI1, BMI2, LZCNT, F16C, and the operating
// system's support for the 256-bit registers (OSXSAVE and XCR0's SSE and AVX state), without which a hypervisor
// may report AVX2 that cannot be used.
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

// The AVX-512 set (raster/simd/isa.h): everything AVX2 needs, AVX-512 F, DQ, BW and VL, and the operating
// system's support for the opmask and 512-bit register state (XCR0 bits 5–7).
bool cpu_has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
  if (!cpu_has_avx2()) return false;
  unsigned a = 0, b = 0, c = 0, d = 0;
  unsigned xcr0_lo = 0, xcr0_hi = 0;
  __asm__ volatile("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0));
  if ((xcr0_lo & 0xE6u) != 0xE6u) return false;
  __cpuid_count(7, 0, a, b, c, d);
  const bool f = b & (1u << 16), dq = b & (1u << 17), bw = b & (1u << 30), vl = b & (1u << 31);
  return f && dq && bw && vl;
#else
  return false;
#endif
}

int fail(const char* what) {
  std::fprintf(stderr, "shadowlab: error: SHADOWLAB_ISA: %s\n", what);
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  const char* forced = std::getenv("SHADOWLAB_ISA");
  if (forced != nullptr && *forced == '\0') forced = nullptr;
  const bool want_auto = forced == nullptr || std::strcmp(forced, "auto") == 0;
  if (!want_auto && std::strcmp(forced, "avx512") != 0 && std::strcmp(forced, "avx2") != 0 &&
      std::strcmp(forced, "scalar") != 0)
    return fail("unknown instruction set (expected avx512, avx2, scalar or auto)");

  if (want_auto || std::strcmp(forced, "avx512") == 0) {
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
    if (cpu_has_avx512()) return cli::isa_avx512::run(argc, argv);
    if (!want_auto) return fail("avx512 was asked for, but this CPU lacks AVX-512 F, DQ, BW or VL (or AVX2)");
#else
    if (!want_auto) return fail("avx512 was asked for, but this build has no AVX-512 path (SHADOWLAB_ISAS)");
#endif
  }
  if (want_auto || std::strcmp(forced, "avx2") == 0) {
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
    if (cpu_has_avx2()) return cli::isa_avx2::run(argc, argv);
    if (!want_auto) return fail("avx2 was asked for, but this CPU lacks AVX2, FMA, BMI1/2, LZCNT or F16C");
#else
    if (!want_auto) return fail("avx2 was asked for, but this build has no AVX2 path (SHADOWLAB_ISAS)");
#endif
  }
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
  return cli::isa_scalar::run(argc, argv);
#else
  if (!want_auto) return fail("scalar was asked for, but this build has no scalar path (SHADOWLAB_ISAS)");
  return fail("this CPU lacks the instruction sets this build has (SHADOWLAB_ISAS)");
#endif
}
