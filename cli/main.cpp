// shadowlab's entry point: picks the instruction set the pipeline runs on, once, before anything else, and hands
// the command line to that build of it (cli/run.cpp, compiled once per set in SHADOWLAB_ISAS: see
// raster/simd/isa.h). The widest set the CPU and the operating system support is taken; the environment
// variable SHADOWLAB_ISA=avx2|scalar|auto forces one. Every set gives bit-identical output
// (tests/cli/isa_dispatch_test.cpp), so the choice changes only the speed. This file is built for plain x86-64
// whatever the sets are: it must run on any CPU to tell it apart.
#include <cstdio>
#include <cstdlib>
#include <cstring>

// One declaration per set built (CMake defines SHADOWLAB_HAVE_ISA_<SET>); the definitions are cli/run.cpp's
// `cli::run` in the set's namespace.
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

// Everything raster/simd/isa.h's AVX2 target enables. libgcc's check of "avx2" includes the operating system's
// support for the 256-bit registers (XGETBV), so a hypervisor that hides them also hides AVX2 here.
bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
         __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("lzcnt") && __builtin_cpu_supports("f16c");
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
  if (!want_auto && std::strcmp(forced, "avx2") != 0 && std::strcmp(forced, "scalar") != 0)
    return fail("unknown instruction set (expected avx2, scalar or auto)");

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
  return fail("this CPU lacks AVX2, the only instruction set this build has (SHADOWLAB_ISAS)");
#endif
}
