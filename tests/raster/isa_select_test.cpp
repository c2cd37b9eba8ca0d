// raster/simd/isa_select.h: the choice among the sets a build has, as SHADOWLAB_ISA asks for it or by the CPU,
// and its one-line refusals; the CPU tests agree with what the kernel reports in /proc/cpuinfo.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "raster/simd/isa_select.h"

namespace {

using raster::simd::BuiltIsas;
using raster::simd::Isa;
using raster::simd::select_isa;
using ::testing::HasSubstr;

constexpr BuiltIsas kAll{true, true, true};

Isa widest_on_this_cpu() {
  return raster::simd::cpu_has_avx512() ? Isa::avx512 : raster::simd::cpu_has_avx2() ? Isa::avx2 : Isa::scalar;
}

TEST(IsaSelect, AutoTakesTheWidestSetTheCpuHas) {
  std::string error;
  for (const char* forced : {static_cast<const char*>(nullptr), "", "auto"}) {
    const auto isa = select_isa(forced, kAll, error);
    ASSERT_TRUE(isa.has_value()) << error;
    EXPECT_EQ(*isa, widest_on_this_cpu());
  }
}

TEST(IsaSelect, AutoFallsBackToTheSetsBuilt) {
  std::string error;
  EXPECT_EQ(select_isa(nullptr, BuiltIsas{false, false, true}, error), Isa::scalar);
  const auto no512 = select_isa(nullptr, BuiltIsas{false, true, true}, error);
  EXPECT_EQ(no512, raster::simd::cpu_has_avx2() ? Isa::avx2 : Isa::scalar);
  const auto none = select_isa(nullptr, BuiltIsas{}, error);
  EXPECT_FALSE(none.has_value());
  EXPECT_EQ(error, "this CPU lacks the instruction sets this build has (SHADOWLAB_ISAS)");
}

TEST(IsaSelect, ForcedSetIsTakenOrRefused) {
  std::string error;
  EXPECT_EQ(select_isa("scalar", kAll, error), Isa::scalar);
  struct Case {
    const char* name;
    Isa isa;
    bool cpu_has;
    const char* refusal;
  };
  for (const Case& c : {Case{"avx2", Isa::avx2, raster::simd::cpu_has_avx2(), "this CPU lacks AVX2"},
                        Case{"avx512", Isa::avx512, raster::simd::cpu_has_avx512(), "this CPU lacks AVX-512"}}) {
    const auto isa = select_isa(c.name, kAll, error);
    if (c.cpu_has) {
      EXPECT_EQ(isa, c.isa) << c.name;
    } else {
      EXPECT_FALSE(isa.has_value()) << c.name;
      EXPECT_THAT(error, HasSubstr(c.refusal));
    }
  }
  EXPECT_FALSE(select_isa("avx512", BuiltIsas{false, true, true}, error).has_value());
  EXPECT_EQ(error, "avx512 was asked for, but this build has no AVX-512 path (SHADOWLAB_ISAS)");
  EXPECT_FALSE(select_isa("avx2", BuiltIsas{true, false, true}, error).has_value());
  EXPECT_EQ(error, "avx2 was asked for, but this build has no AVX2 path (SHADOWLAB_ISAS)");
  EXPECT_FALSE(select_isa("scalar", BuiltIsas{true, true, false}, error).has_value());
  EXPECT_EQ(error, "scalar was asked for, but this build has no scalar path (SHADOWLAB_ISAS)");
}

TEST(IsaSelect, UnknownNameIsRefused) {
  std::string error;
  for (const char* name : {"sse2", "AVX2", "avx", "avx512 "}) {
    EXPECT_FALSE(select_isa(name, kAll, error).has_value()) << name;
    EXPECT_EQ(error, "unknown instruction set (expected avx512, avx2, scalar or auto)");
  }
  EXPECT_STREQ(raster::simd::isa_name(Isa::avx512), "avx512");
  EXPECT_STREQ(raster::simd::isa_name(Isa::avx2), "avx2");
  EXPECT_STREQ(raster::simd::isa_name(Isa::scalar), "scalar");
}

// The kernel's flags for the first CPU (empty where /proc/cpuinfo is missing).
std::string cpuinfo_flags() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("flags", 0) == 0) return line.substr(line.find(':') + 1) + " ";
  return {};
}

TEST(IsaSelect, CpuTestsAgreeWithTheKernel) {
  const std::string flags = cpuinfo_flags();
  if (flags.empty()) GTEST_SKIP() << "no /proc/cpuinfo";
  // Appended rather than `" " + std::string(f)`, which GCC 12 reports as an overflow (-Wstringop-overflow, a false
  // positive).
  auto has = [&](const char* f) { return flags.find(std::string(" ").append(f).append(" ")) != std::string::npos; };
  const bool avx2 = has("avx2") && has("fma") && has("bmi1") && has("bmi2") && has("f16c") && has("abm");
  EXPECT_EQ(raster::simd::cpu_has_avx2(), avx2);
  const bool avx512 = avx2 && has("avx512f") && has("avx512dq") && has("avx512bw") && has("avx512vl");
  EXPECT_EQ(raster::simd::cpu_has_avx512(), avx512);
}

}  // namespace
