// shadowlab's entry point: picks the instruction set the pipeline runs on, once, before anything else, and hands
// the command line to that build of it (cli/run.cpp, compiled once per set in SHADOWLAB_ISAS: see
// raster/simd/isa.h). raster/simd/isa_select.h makes the choice: the widest set the CPU and the operating system
// support, or the one the environment variable SHADOWLAB_ISA=avx512|avx2|scalar|auto forces. Every set gives bit-identical output
// (tests/cli/isa_dispatch_test.cpp), so the choice changes only the speed. This file is built for plain x86-64
// whatever the sets are: it must run on any CPU to tell it apart.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "raster/simd/isa_select.h"

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

}  // namespace

int main(int argc, char** argv) {
  raster::simd::BuiltIsas built;
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
  built.avx512 = true;
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
  built.avx2 = true;
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
  built.scalar = true;
#endif
  std::string error;
  const auto isa = raster::simd::select_isa(std::getenv("SHADOWLAB_ISA"), built, error);
  if (!isa) {
    std::fprintf(stderr, "shadowlab: error: SHADOWLAB_ISA: %s\n", error.c_str());
    return kExitBadInput;
  }
  switch (*isa) {
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
    case raster::simd::Isa::avx512: return cli::isa_avx512::run(argc, argv);
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
    case raster::simd::Isa::avx2: return cli::isa_avx2::run(argc, argv);
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
    case raster::simd::Isa::scalar: return cli::isa_scalar::run(argc, argv);
#endif
    default: break;
  }
  return kExitBadInput;  // not reached: select_isa picks among the sets built
}
