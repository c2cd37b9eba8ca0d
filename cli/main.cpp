// shadowlab's entry point: picks the instruction set the pipeline runs on, once, before anything else, and hands
// the command line to that build of it (cli/run.cpp, compiled once per set in SHADOWLAB_ISAS: see
// raster/simd/isa.h). raster/simd/isa_select.h makes the choice: the widest set the CPU and the operating system
// support, or the one the environment variable SHADOWLAB_ISA=avx512|avx2|scalar|auto forces. Every set gives
// bit-identical output (tests/cli/isa_dispatch_test.cpp), so the choice changes only the speed. This file is built
// for plain x86-64 whatever the sets are: it must run on any CPU to tell them apart.
#define SHADOWLAB_ENTRY_NAMESPACE cli
#include "raster/simd/isa_entry.h"

// Exit code 2 and one line where SHADOWLAB_ISA names a set that cannot run, as for any other bad input.
int main(int argc, char** argv) { return raster::simd::run_entry("shadowlab", argc, argv); }
