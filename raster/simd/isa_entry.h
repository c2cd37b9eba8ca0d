// An entry point's dispatch to the build of its program for each instruction set (isa_select.h). The including
// file defines SHADOWLAB_ENTRY_NAMESPACE, the namespace whose isa_<set>::run(argc, argv) each set's build of the
// program defines (cli for the shadowlab executable, bench for a benchmark program), and calls run_entry once;
// CMake defines SHADOWLAB_HAVE_ISA_<SET> for each set built. Included once per program, by its main.cpp.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

#include "raster/simd/isa_select.h"

#if !defined(SHADOWLAB_ENTRY_NAMESPACE)
#error "define SHADOWLAB_ENTRY_NAMESPACE (the namespace of the sets' run functions) before including isa_entry.h"
#endif

#if defined(SHADOWLAB_HAVE_ISA_AVX512)
namespace SHADOWLAB_ENTRY_NAMESPACE::isa_avx512 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
namespace SHADOWLAB_ENTRY_NAMESPACE::isa_avx2 {
int run(int argc, char** argv);
}
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
namespace SHADOWLAB_ENTRY_NAMESPACE::isa_scalar {
int run(int argc, char** argv);
}
#endif

namespace raster::simd {

// Runs the chosen set's run(argc, argv); or prints `PROGRAM: error: SHADOWLAB_ISA: why` and returns 2 when none
// can run. on_choice, if given, is told the set first.
inline int run_entry(const char* program, int argc, char** argv, void (*on_choice)(Isa) = nullptr) {
  int (*run[3])(int, char**) = {nullptr, nullptr, nullptr};  // by Isa; null where the set is not built
#if defined(SHADOWLAB_HAVE_ISA_AVX512)
  run[int(Isa::avx512)] = SHADOWLAB_ENTRY_NAMESPACE::isa_avx512::run;
#endif
#if defined(SHADOWLAB_HAVE_ISA_AVX2)
  run[int(Isa::avx2)] = SHADOWLAB_ENTRY_NAMESPACE::isa_avx2::run;
#endif
#if defined(SHADOWLAB_HAVE_ISA_SCALAR)
  run[int(Isa::scalar)] = SHADOWLAB_ENTRY_NAMESPACE::isa_scalar::run;
#endif
  const BuiltIsas built{run[int(Isa::avx512)] != nullptr, run[int(Isa::avx2)] != nullptr,
                        run[int(Isa::scalar)] != nullptr};
  std::string error;
  const auto isa = select_isa(std::getenv("SHADOWLAB_ISA"), built, error);  // only ever a set that is built
  if (!isa) {
    std::fprintf(stderr, "%s: error: SHADOWLAB_ISA: %s\n", program, error.c_str());
    return 2;
  }
  if (on_choice) on_choice(*isa);
  return run[int(*isa)](argc, argv);
}

}  // namespace raster::simd
