// End-to-end tests of `shadowlab render` with per-caster projective shadows: the per-frame cache line of
// --stats (still frames reuse every map, --animate rebuilds the moving ones), the maps as EXR, and bad values
// of the projective options as one error line naming the option, exit code 2 and no output file.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenes/io/exr_map.h"
#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

using testsupport::Outcome;
using testsupport::shadowlab;

// The `frame K: maps rebuilt R, reused U, skipped S` lines of stdout, in order.
std::vector<std::string> cache_lines(const std::string& out) {
  std::vector<std::string> lines;
  const std::regex line("^frame [0-9]+: maps rebuilt [0-9]+, reused [0-9]+, skipped [0-9]+$");
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);)
    if (std::regex_match(l, line)) lines.push_back(l);
  return lines;
}

class ProjectiveCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = testsupport::temp_dir(std::string("projcli_") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void expect_bad(const std::string& args, const std::string& where) {
    testsupport::expect_bad_run(dir, args + " --out bad.png", where, "bad.png");
  }
  fs::path dir;
};

TEST_F(ProjectiveCli, StillFramesReuseEveryMap) {
  const Outcome r = shadowlab(dir, "render projective --size 96x54 --threads 0 --frames 3 --stats --out f.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(cache_lines(r.out), (std::vector<std::string>{"frame 1: maps rebuilt 5, reused 0, skipped 0",
                                                          "frame 2: maps rebuilt 0, reused 5, skipped 0",
                                                          "frame 3: maps rebuilt 0, reused 5, skipped 0"}))
      << r.out;
  EXPECT_TRUE(fs::exists(dir / "f.png"));
}

TEST_F(ProjectiveCli, AnimatedFramesRebuildTheWalkers) {
  const Outcome r = shadowlab(dir, "render projective --size 96x54 --threads 0 --frames 3 --animate --fps 24 "
                                   "--stats --projective-mode single-pass --out f.png --maps maps");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(cache_lines(r.out), (std::vector<std::string>{"frame 1: maps rebuilt 5, reused 0, skipped 0",
                                                          "frame 2: maps rebuilt 5, reused 0, skipped 0",
                                                          "frame 3: maps rebuilt 5, reused 0, skipped 0"}))
      << r.out;
  size_t maps = 0;
  for (const auto& e : fs::directory_iterator(dir / "maps")) {
    const scenes::io::ExrMap m = scenes::io::read_exr_map(e.path());
    EXPECT_EQ(m.technique, "projective") << e.path();
    EXPECT_EQ(m.encoding, "caster-mask");
    EXPECT_EQ(m.width, 256);
    ++maps;
  }
  EXPECT_EQ(maps, 5u);
}

// The command line's camera and light choices hold for every frame of an animation, not only the first: an
// orbit camera stays where the first frame put it while the walkers move.
TEST_F(ProjectiveCli, AnimatedFramesKeepTheChosenCamera) {
  Outcome r = shadowlab(dir, "render projective --size 48x27 --threads 0 --frames 3 --animate --camera orbit:30,20 "
                             "--light 0 --out 'o_%d.png'");
  ASSERT_EQ(r.code, 0) << r.err;
  r = shadowlab(dir, "render projective --size 48x27 --threads 0 --camera orbit:30,20 --out still.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(testsupport::slurp(dir / "o_1.png"), testsupport::slurp(dir / "still.png"));
  EXPECT_NE(testsupport::slurp(dir / "o_1.png"), testsupport::slurp(dir / "o_3.png")) << "the walkers moved";
}

TEST_F(ProjectiveCli, BadValuesNameTheOption) {
  expect_bad("render projective --size 32x18 --projective-mode twice", "--projective-mode");
  expect_bad("render projective --size 32x18 --projective-textures 0", "--projective-textures");
  expect_bad("render projective --size 32x18 --projective-textures 9", "--projective-textures");
  expect_bad("render tutorial --size 32x18 --animate", "--animate");
  expect_bad("render projective --size 32x18 --animate --fps 0", "--fps");
  expect_bad("render projective --size 32x18 --animate --fps -2", "--fps");
  expect_bad("render projective --size 32x18 --fps 30", "--fps");  // a frame rate with nothing to animate
  expect_bad("render projective --size 32x18 --blur-passes 17", "--blur-passes");
  expect_bad("render projective --size 32x18 --blur-passes 1 --blur-offset 2", "--blur-offset");
  expect_bad("render projective --size 32x18 --blur-offset 0.5", "--blur-offset");
  expect_bad("render projective --size 32x18 --fade-lookup curve", "--fade-lookup");
  expect_bad("render projective --size 32x18 --fade-lookup texture", "--fade-lookup");
  expect_bad("render projective --size 32x18 --fade-end 2 --fade-lookup texture --fade-table 1,2", "--fade-table");
  expect_bad("render projective --size 32x18 --fade-end 2 --fade-table 1,0", "--fade-table");
}

}  // namespace
