// The instruction set a translation unit's pipeline code is built for, as a namespace: every namespace block of
// raster/, shading/, scenes/{io,frame,reference}/ and cli/ opens SHADOWLAB_ISA_BEGIN and closes SHADOWLAB_ISA_END,
// so the same sources compiled for AVX2 and for plain x86-64 give distinct symbols (raster::isa_avx2::Renderer,
// raster::isa_scalar::Renderer) that live side by side in one binary; cli/main.cpp picks one when it starts
// (raster/simd/isa_select.h), and so does each benchmark program (bench/isa_main.cpp), whose code is in
// SHADOWLAB_ISA_BEGIN blocks too.
//
// Why a namespace and not just a compiler flag: an inline function or template compiled in two translation
// units becomes one symbol at link time, and the linker keeps either copy. If AVX2 units were simply built
// with -mavx2, a copy built with AVX2 instructions could serve the scalar path on a CPU without AVX2. With the
// namespace, our own code cannot mix; and where the libraries are built for several instruction sets
// (SHADOWLAB_ISAS names more than one), the AVX2 target is switched on by a pragma around our namespace blocks
// only, so the standard library's, GLM's and oneTBB's inline functions, instantiated outside them, stay plain
// x86-64 code in every unit. Headers with plain data only (raster/formats.h, raster/state.h,
// shading/tone_map.h, shading/techniques/vocabulary.h) stay outside: their types are shared by every path and
// by the scene library, which is built once. So does the choice of set (raster/simd/isa_select.h and .cpp,
// isa_entry.h), which must run on any CPU.
//
// A translation unit defines exactly one of SHADOWLAB_SIMD_AVX2 and SHADOWLAB_SIMD_SCALAR (CMake does, from the
// library it belongs to). The AVX-512 set is the AVX2 set plus SHADOWLAB_SIMD_AVX512: every AVX2 code path is
// used as it is (compiled with the wider set's encodings), and where the code has sixteen-lane work (the
// depth-only back end, vec.h) it takes one 512-bit register instead of two halves. Its features are AVX-512 F,
// VL, BW and DQ (Skylake-SP, Ice Lake, Sapphire Rapids and later Intel server parts, AMD Zen 4 and later). Built
// with the flags on the command line (a one-set build, and the tests), the pragma is not needed and not emitted.
#pragma once

#if defined(SHADOWLAB_SIMD_AVX2) == defined(SHADOWLAB_SIMD_SCALAR)
#error "define exactly one of SHADOWLAB_SIMD_AVX2 and SHADOWLAB_SIMD_SCALAR (CMake does this per library)"
#endif
#if defined(SHADOWLAB_SIMD_AVX512) && !defined(SHADOWLAB_SIMD_AVX2)
#error "SHADOWLAB_SIMD_AVX512 extends the AVX2 set: define SHADOWLAB_SIMD_AVX2 too (CMake does this per library)"
#endif

#if defined(SHADOWLAB_SIMD_AVX512)
#define SHADOWLAB_ISA_NAME "avx512"
#if defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__) && defined(__F16C__) && defined(__LZCNT__) && \
    defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__) && defined(__AVX512DQ__)
#define SHADOWLAB_ISA_BEGIN inline namespace isa_avx512 {
#define SHADOWLAB_ISA_END }
#elif defined(__GNUC__) && !defined(__clang__)
// The features raster/simd/isa_select.cpp checks before this path is taken.
#define SHADOWLAB_ISA_BEGIN                                                                   \
  _Pragma("GCC push_options")                                                                 \
  _Pragma("GCC target(\"avx2,fma,bmi,bmi2,lzcnt,f16c,avx512f,avx512vl,avx512bw,avx512dq\")") \
  inline namespace isa_avx512 {
#define SHADOWLAB_ISA_END \
  }                       \
  _Pragma("GCC pop_options")
#else
#error "an AVX-512 path without its flags on the command line needs GCC's target pragma: configure SHADOWLAB_ISAS=avx512 alone"
#endif
#elif defined(SHADOWLAB_SIMD_AVX2)
#define SHADOWLAB_ISA_NAME "avx2"
#if defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__) && defined(__F16C__) && defined(__LZCNT__)
#define SHADOWLAB_ISA_BEGIN inline namespace isa_avx2 {
#define SHADOWLAB_ISA_END }
#elif defined(__GNUC__) && !defined(__clang__)
// The features raster/simd/isa_select.cpp checks before this path is taken.
#define SHADOWLAB_ISA_BEGIN                                  \
  _Pragma("GCC push_options")                                \
  _Pragma("GCC target(\"avx2,fma,bmi,bmi2,lzcnt,f16c\")") \
  inline namespace isa_avx2 {
#define SHADOWLAB_ISA_END \
  }                       \
  _Pragma("GCC pop_options")
#else
#error "an AVX2 path without -mavx2 on the command line needs GCC's target pragma: configure SHADOWLAB_ISAS=avx2 alone"
#endif
#else
#define SHADOWLAB_ISA_NAME "scalar"
#define SHADOWLAB_ISA_BEGIN inline namespace isa_scalar {
#define SHADOWLAB_ISA_END }
#endif
