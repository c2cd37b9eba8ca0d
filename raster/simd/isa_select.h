// Which of the built instruction sets (raster/simd/isa.h) a program runs: the widest one the CPU and the operating
// system support, or the one the environment variable SHADOWLAB_ISA names (avx512, avx2, scalar or auto). The
// shadowlab executable (cli/main.cpp) and the benchmark programs (bench/isa_main.cpp) decide with it once, when
// they start. Built for plain x86-64 whatever the sets are, outside every set's namespace: it must run on any CPU to
// tell them apart.
#pragma once
#include <optional>
#include <string>

namespace raster::simd {

enum class Isa { scalar, avx2, avx512 };

// Everything isa.h's AVX2 set enables (AVX2, FMA, BMI1, BMI2, LZCNT, F16C) with the operating system's support for
// the 256-bit registers; and the AVX-512 set's F, DQ, BW and VL on top, with the opmask and 512-bit state.
bool cpu_has_avx2();
bool cpu_has_avx512();

struct BuiltIsas {
  bool avx512 = false, avx2 = false, scalar = false;
};

// The set to run among `built`: `forced` (SHADOWLAB_ISA's value; null, empty or "auto" for the widest the CPU
// has). Nothing, with `error` saying why in one line, when the name is unknown, the build lacks the set, or the
// CPU cannot run it.
std::optional<Isa> select_isa(const char* forced, BuiltIsas built, std::string& error);

const char* isa_name(Isa isa);

}  // namespace raster::simd
