// Every benchmark program's entry point: runs the program's build for the instruction set the shadowlab
// executable would take on this machine (raster/simd/isa_select.h: the widest the CPU has, or SHADOWLAB_ISA's),
// so that a benchmark times what users run. Each program's source defines bench::run once per set in
// SHADOWLAB_ISAS (bench/CMakeLists.txt); the set taken is printed in Google Benchmark's context (simd_path, also
// in the JSON output) and in the programs' summaries. Built for plain x86-64, like cli/main.cpp.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <benchmark/benchmark.h>

#include "raster/simd/isa_select.h"

#if defined(SHADOWLAB_HAVE_ISA_AVX512)
namespace bench::isa_avx512 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
namespace bench::isa_avx2 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
namespace bench::isa_scalar {
int run(int argc, char** argv);
}
#endif

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
    std::fprintf(stderr, "%s: error: SHADOWLAB_ISA: %s\n", argc > 0 ? argv[0] : "benchmark", error.c_str());
    return 2;
  }
  benchmark::AddCustomContext("simd_path", raster::simd::isa_name(*isa));
  switch (*isa) {
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
    case raster::simd::Isa::avx512: return bench::isa_avx512::run(argc, argv);
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
    case raster::simd::Isa::avx2: return bench::isa_avx2::run(argc, argv);
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
    case raster::simd::Isa::scalar: return bench::isa_scalar::run(argc, argv);
#endif
    default: break;
  }
  return 2;  // not reached: select_isa picks among the sets built
}
