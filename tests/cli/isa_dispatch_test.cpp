// The one executable's instruction sets (cli/main.cpp, raster/simd/isa.h): SHADOWLAB_ISA forces a path, --version
// and --json say which one ran, a bad value is refused in one line, every path writes the same bytes (frames,
// per-pixel channels and every shadow map of each technique family, AVX2 and AVX-512 each against scalar, where
// the CPU has them), and the executable runs on a CPU without AVX at all (QEMU's user-mode emulation of a
// Nehalem; skipped where qemu-x86_64 is missing), where it takes the scalar path by itself. Where the build holds
// one set (SHADOWLAB_ISAS, e.g. the clang sanitizer build), the comparisons are skipped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using testsupport::Outcome;
using testsupport::shadowlab;

bool built(const std::string& isa) {
  // Appended rather than `"," + std::string(...)`: GCC 12 warns about that form (-Wstringop-overflow, a false
  // positive).
  const std::string list = std::string(",").append(SHADOWLAB_BUILT_ISAS).append(",");
  return list.find(std::string(",").append(isa).append(",")) != std::string::npos;
}

// Whether this machine runs the path of set `isa`: the executable's own answer (raster/simd/isa_select.cpp reads
// CPUID for it).
bool cpu_runs(const std::string& isa) {
  static std::map<std::string, bool> known;
  if (!known.count(isa)) {
    const Outcome r = shadowlab(testsupport::temp_dir("cli_isa_probe"), "--version", "SHADOWLAB_ISA=" + isa);
    known[isa] = r.code == 0 && r.out.find("SIMD path " + isa) != std::string::npos;
  }
  return known[isa];
}
bool cpu_has_avx2() { return cpu_runs("avx2"); }

// Whether this CPU has what the AVX-512 set needs, asked of the compiler's runtime rather than of the program
// under test, so that a dispatcher that wrongly says no on an AVX-512 machine fails here instead of quietly
// comparing less (GCC's and clang's checks include the operating system's support for the 512-bit state).
bool cpu_has_avx512() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
#else
  return false;
#endif
}

// Every file under `dir`, by path relative to it, with its bytes.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "stdout.txt" && e.path().filename() != "stderr.txt")
      out[fs::relative(e.path(), dir).string()] = testsupport::slurp(e.path());
  return out;
}

TEST(CliIsa, VersionNamesTheForcedPath) {
  if (!built("scalar") || !built("avx2")) GTEST_SKIP() << "this build holds one instruction set: " SHADOWLAB_BUILT_ISAS;
  const fs::path dir = testsupport::temp_dir("cli_isa_version");
  Outcome r = shadowlab(dir, "--version", "SHADOWLAB_ISA=scalar");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("SIMD path scalar"));
  // auto takes the widest set the CPU has.
  const bool avx512 = built("avx512") && cpu_has_avx512();
  r = shadowlab(dir, "--version", "SHADOWLAB_ISA=auto");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr(avx512 ? "SIMD path avx512" : cpu_has_avx2() ? "SIMD path avx2" : "SIMD path scalar"));
  r = shadowlab(dir, "--version", "SHADOWLAB_ISA=avx2");
  if (cpu_has_avx2()) {
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.out, ::testing::HasSubstr("SIMD path avx2"));
  } else {
    EXPECT_EQ(r.code, 2);
    EXPECT_THAT(r.err, ::testing::StartsWith("shadowlab: error: SHADOWLAB_ISA: avx2 was asked for"));
  }
  if (built("avx512")) {
    // Asked for on a CPU without AVX-512 (this development machine, most CI runners): one line, exit code 2.
    r = shadowlab(dir, "--version", "SHADOWLAB_ISA=avx512");
    if (avx512) {
      EXPECT_EQ(r.code, 0) << r.err;
      EXPECT_THAT(r.out, ::testing::HasSubstr("SIMD path avx512"));
    } else {
      EXPECT_EQ(r.code, 2);
      EXPECT_EQ(r.err, "shadowlab: error: SHADOWLAB_ISA: avx512 was asked for, but this CPU lacks AVX-512 F, DQ, BW or "
                       "VL (or AVX2)\n");
      EXPECT_EQ(r.out, "");
    }
  }
  // The documents scripts keep say which path made them.
  r = shadowlab(dir, "list --json", "SHADOWLAB_ISA=scalar");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("\"simd\": \"scalar\""));
}

TEST(CliIsa, UnknownPathIsRefusedInOneLine) {
  const fs::path dir = testsupport::temp_dir("cli_isa_bad");
  const Outcome r = shadowlab(dir, "render tutorial --size 16x16 --out o.png", "SHADOWLAB_ISA=avx10");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "shadowlab: error: SHADOWLAB_ISA: unknown instruction set (expected avx512, avx2, scalar or auto)\n");
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

// One command line per family of passes the paths could disagree on: depth-only map passes (every format),
// PCF and Poisson lookups, the directional family, the filterable maps' encode, blur and mip passes, PCSS,
// point and hemispherical lights, projective textures and the irregular z-buffer. Each writes the frame, its
// per-pixel channels (floats: no 8-bit rounding hides a difference) and every shadow map.
// A sphere of 24,320 triangles over a plane: its shadow map's draw is large enough (renderer.h, kStreamBinsBytes) to
// bin its records with non-temporal stores (simd::stream_line, one 64-byte store with AVX-512, two 32-byte halves
// with AVX2, a plain copy in the scalar set), which the built-in scenes are too small to reach.
fs::path dense_scene() {
  const fs::path path = testsupport::temp_dir("cli_isa_dense") / "dense.json";
  std::ofstream(path) << R"({
  "version": 1,
  "name": "dense",
  "materials": [{"name": "grey", "base_color": [0.7, 0.7, 0.7, 1.0]}],
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [8.0, 8.0]}, "material": "grey"},
    {"name": "ball", "primitive": {"type": "sphere", "radius": 1.5, "segments": 128, "rings": 96},
     "transform": {"translate": [0.0, 1.6, 0.0]}, "material": "grey"}
  ],
  "cameras": [{"name": "main", "position": [0.0, 4.0, 9.0], "target": [0.0, 1.0, 0.0],
               "perspective": {"fovy": 45.0, "near": 0.5, "far": 40.0}}],
  "lights": [{"name": "sun", "type": "directional", "intensity": 100000.0, "direction": [-0.5, -2.0, -1.0],
              "shadow": {"technique": "shadowmap"}}]
}
)";
  return path;
}

TEST(CliIsa, EveryPathWritesTheScalarPathsBytes) {
  if (!built("scalar") || !built("avx2")) GTEST_SKIP() << "this build holds one instruction set: " SHADOWLAB_BUILT_ISAS;
  std::vector<std::string> wide;  // the sets compared with scalar: those built that this CPU runs
  if (cpu_has_avx2()) wide.push_back("avx2");
  if (built("avx512") && cpu_has_avx512()) wide.push_back("avx512");
  if (wide.empty()) GTEST_SKIP() << "this CPU has no AVX2 path to compare with";
  if (built("avx512") && !cpu_has_avx512())
    std::cout << "[   NOTE   ] avx512 is built but this CPU lacks it: only avx2 is compared with scalar here\n";
  const std::string out = " --size 96x64 --shadow-size 256 --threads 2 --out f.png --aov-out aov.exr --maps maps";
  const std::vector<std::string> cases = {
      "render tutorial --technique shadowmap --filter pcf --depth-format d16" + out,
      "render tutorial --technique shadowmap --filter poisson --bias slope --depth-format d24" + out,
      "render tutorial --technique cascades" + out,
      "render tutorial --technique lispsm" + out,
      "render tutorial --technique frustum-faces" + out,
      "render tutorial --technique vsm" + out,
      "render tutorial --technique evsm4 --blur-radius 3" + out,
      "render tutorial --technique esm --moment-mips nearest" + out,
      "render tutorial --technique pcss" + out,
      "render tutorial --technique irregular" + out,
      "render tutorial-spot --technique pcss" + out,
      "render paraboloid --technique cube" + out,
      "render paraboloid --technique cube --soft-shadows pcss --light-radius 0.15" + out,
      "render paraboloid --technique paraboloid" + out,
      "render pyramid --technique pyramid" + out,
      "render projective" + out,
      "render duel" + out,
      "render " + dense_scene().string() + " --technique shadowmap" + out,
  };
  auto run = [&](size_t i, const std::string& isa) {
    const fs::path dir = testsupport::temp_dir("cli_isa_" + std::to_string(i) + "_" + isa);
    const Outcome r = shadowlab(dir, cases[i], "SHADOWLAB_ISA=" + isa);
    EXPECT_EQ(r.code, 0) << isa << ": " << cases[i] << "\n" << r.err;
    return files_under(dir);
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::map<std::string, std::string> scalar = run(i, "scalar");
    ASSERT_TRUE(scalar.count("f.png") && scalar.count("aov.exr")) << cases[i];  // (irregular: no map)
    for (const std::string& isa : wide) {
      const std::map<std::string, std::string> other = run(i, isa);
      ASSERT_EQ(scalar.size(), other.size()) << isa << ": " << cases[i];
      for (const auto& [name, bytes] : scalar) {
        ASSERT_TRUE(other.count(name)) << cases[i] << ": " << isa << " wrote no " << name;
        EXPECT_TRUE(bytes == other.at(name)) << cases[i] << ": " << name << " differs between scalar and " << isa;
      }
    }
  }
}

// The binary built with -mavx2 throughout died here with SIGILL before main (checked with the previous build):
// this is what "one binary that runs anywhere" has to survive, static initialisers included.
TEST(CliIsa, RunsOnACpuWithoutAvx) {
  if (!built("scalar")) GTEST_SKIP() << "this build has no scalar path: " SHADOWLAB_BUILT_ISAS;
  if (std::system("command -v qemu-x86_64 >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "qemu-x86_64 (Debian qemu-user) is not installed";
  const fs::path dir = testsupport::temp_dir("cli_isa_qemu");
  const std::string nehalem = "qemu-x86_64 -cpu Nehalem";
  Outcome r = shadowlab(dir, "--version", nehalem);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("SIMD path scalar"));
  r = shadowlab(dir, "--version", "SHADOWLAB_ISA=avx2 " + nehalem);
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("shadowlab: error: SHADOWLAB_ISA: avx2 was asked for, but this CPU lacks"));
  if (built("avx512")) {
    r = shadowlab(dir, "--version", "SHADOWLAB_ISA=avx512 " + nehalem);
    EXPECT_EQ(r.code, 2);
    EXPECT_THAT(r.err, ::testing::HasSubstr("shadowlab: error: SHADOWLAB_ISA: avx512 was asked for, but this CPU lacks"));
  }
  // A frame and its maps on the emulated CPU, byte for byte those of the host's own default path.
  const std::string args =
      "render tutorial --technique vsm --size 64x48 --shadow-size 128 --threads 2 --out f.png --maps maps";
  r = shadowlab(dir, args, nehalem);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::map<std::string, std::string> emulated = files_under(dir);
  const fs::path host = testsupport::temp_dir("cli_isa_qemu_host");
  ASSERT_EQ(shadowlab(host, args).code, 0);
  const std::map<std::string, std::string> native = files_under(host);
  ASSERT_EQ(emulated.size(), native.size());
  for (const auto& [name, bytes] : native) {
    ASSERT_TRUE(emulated.count(name)) << name;
    EXPECT_TRUE(bytes == emulated.at(name)) << name << " differs on the emulated CPU";
  }
}

}  // namespace
