// Every benchmark program's entry point: runs the program's build for the instruction set the shadowlab
// executable would take on this machine (raster/simd/isa_select.h: the widest the CPU has, or SHADOWLAB_ISA's),
// so that a benchmark times what users run. Each program's source defines bench::run once per set in
// SHADOWLAB_ISAS (bench/CMakeLists.txt); the set taken is printed in Google Benchmark's context (simd_path, also
// in the JSON output) and in the programs' summaries. Built for plain x86-64, like cli/main.cpp.
#include <benchmark/benchmark.h>

#define SHADOWLAB_ENTRY_NAMESPACE bench
#include "raster/simd/isa_entry.h"

int main(int argc, char** argv) {
  return raster::simd::run_entry(argc > 0 ? argv[0] : "benchmark", argc, argv, [](raster::simd::Isa isa) {
    benchmark::AddCustomContext("simd_path", raster::simd::isa_name(isa));
  });
}
