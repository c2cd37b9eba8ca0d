// Writes onto a real full filesystem: a 64 KiB tmpfs mounted for the test in a private mount namespace
// (`unshare -rm`, which needs no privilege where user namespaces are enabled; `unshare -m` as root otherwise),
// filled to the last block before shadowlab runs. Every run must exit 2 with one line, keep the file that was
// there byte for byte, and leave no temporary and no half of a batch. Skipped, saying why, where nothing can
// be mounted (CI containers without user namespaces or CAP_SYS_ADMIN).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

using testsupport::Outcome;
using testsupport::shadowlab;
using testsupport::slurp;

// Which unshare invocation can mount a tmpfs here, or "" when none can.
std::string mount_prefix(const fs::path& dir) {
  const fs::path probe = dir / "probe";
  fs::create_directories(probe);
  for (const char* prefix : {"unshare -rm", "unshare -m"}) {
    const std::string cmd = std::string(prefix) + " sh -c 'mount -t tmpfs -o size=64k none \"" + probe.string() +
                            "\"' >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return prefix;
  }
  return "";
}

class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = testsupport::temp_dir(std::string("full_disk_") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
    prefix = mount_prefix(dir);
    if (prefix.empty())
      GTEST_SKIP() << "skipped: cannot mount a tmpfs here (unshare -rm and unshare -m both refused; needs user "
                      "namespaces or CAP_SYS_ADMIN)";
    // A good frame and a map made on the ordinary filesystem.
    const Outcome r = shadowlab(dir, "render tutorial --size 32x24 --shadow-size 32 --out good.png --maps good");
    ASSERT_EQ(r.code, 0) << r.err;
  }

  // Mounts a 64 KiB tmpfs at dir/full holding `seed` files (copied from dir), fills it, runs `shadowlab ARGS`
  // in dir, and records the exit code, stderr, the listing of the tmpfs and checksums of what is on it.
  Outcome run_on_full_disk(const std::string& seed, const std::string& args) {
    fs::create_directories(dir / "full");
    const std::string script =
        "set -u; cd '" + dir.string() + "' || exit 90; mount -t tmpfs -o size=64k none full || exit 91; " +
        (seed.empty() ? "" : "cp " + seed + " full/ || exit 92; ") +
        "dd if=/dev/zero of=full/fill bs=1k >/dev/null 2>&1; "  // until no space is left
        "'" SHADOWLAB_CLI "' " + args + " >stdout.txt 2>stderr.txt; echo $? >code.txt; "
        "(cd full && find . -mindepth 1 ! -name fill | sort >../listing.txt; "
        " find . -type f ! -name fill -exec md5sum {} + | sort -k2 >../sums.txt)";
    const std::string cmd = prefix + " sh -c \"" + escape(script) + "\"";
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(status, 0) << cmd;
    return {std::atoi(slurp(dir / "code.txt").c_str()), slurp(dir / "stdout.txt"), slurp(dir / "stderr.txt")};
  }
  static std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
      if (c == '"' || c == '\\' || c == '$' || c == '`') out += '\\';
      out += c;
    }
    return out;
  }
  std::string sums_of(const std::string& files) {
    const std::string cmd = "cd '" + dir.string() + "' && md5sum " + files + " | sed 's|  |  ./|' | sort -k2 >expected.txt";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return slurp(dir / "expected.txt");
  }
  void expect_one_line_failure(const Outcome& r, const std::string& file) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_THAT(r.err, ::testing::MatchesRegex("shadowlab: error: [^\n]*" + file + "[^\n]*: [^\n]+\n")) << r.err;
  }

  fs::path dir;
  std::string prefix;
};

TEST_F(FullDisk, RenderKeepsThePreviousFrame) {
  const Outcome r = run_on_full_disk("good.png", "render tutorial --size 64x48 --shadow-size 32 --out full/good.png");
  expect_one_line_failure(r, "good.png");
  EXPECT_EQ(slurp(dir / "listing.txt"), "./good.png\n");  // no temporary beside it
  EXPECT_EQ(slurp(dir / "sums.txt"), sums_of("good.png"));
}

TEST_F(FullDisk, RenderWithMapsWritesNothingNew) {
  const Outcome r = run_on_full_disk(
      "good.png", "render tutorial --size 64x48 --shadow-size 32 --out full/good.png --maps full/maps");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_THAT(r.err, ::testing::MatchesRegex("shadowlab: error: [^\n]+: [^\n]+\n")) << r.err;
  // The maps folder the run made is removed with its temporaries.
  EXPECT_EQ(slurp(dir / "listing.txt"), "./good.png\n");
  EXPECT_EQ(slurp(dir / "sums.txt"), sums_of("good.png"));
}

// OpenEXR's own file stream dropped the error of its last flush: a small map on a full disk came out as a
// 0-byte file and the run exited 0. Maps are now encoded in memory and written with every failure checked.
TEST_F(FullDisk, ShadowmapKeepsThePreviousMap) {
  std::ofstream(dir / "tri.json") << R"({"objects": [{"mesh": {"positions": [-1, -1, 0.5, 1, -1, 0.5, 0, 1, 0.5],
                                          "indices": [0, 1, 2]}}]})";
  std::ofstream(dir / "m.json") << R"({"view_proj": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})";
  ASSERT_EQ(shadowlab(dir, "shadowmap --scene tri.json --light-matrix m.json --size 16x16 --format d32f --out m.exr")
                .code, 0);
  const Outcome r = run_on_full_disk(
      "m.exr", "shadowmap --scene tri.json --light-matrix m.json --size 64x64 --format d16 --out full/m.exr");
  expect_one_line_failure(r, "m.exr");
  EXPECT_EQ(slurp(dir / "listing.txt"), "./m.exr\n");
  EXPECT_EQ(slurp(dir / "sums.txt"), sums_of("m.exr"));
}

// check --update on a full disk: one line naming the golden, the old goldens untouched.
TEST_F(FullDisk, CheckUpdateKeepsTheGoldens) {
  std::ofstream(dir / "manifest.json") << R"({"goldens": "full/g", "entries": [
      {"name": "a", "scene": "tutorial", "args": ["--size", "48x27", "--shadow-size", "32"]},
      {"name": "b", "scene": "duel", "args": ["--size", "48x27", "--shadow-size", "32"]}]})";
  const Outcome r = run_on_full_disk("", "check manifest.json --update");
  expect_one_line_failure(r, "full/g/[ab].png");
  EXPECT_EQ(slurp(dir / "listing.txt"), "");  // no goldens folder left either
}

TEST_F(FullDisk, InspectPreviewKeepsThePreviousFile) {
  const fs::path map = *fs::directory_iterator(dir / "good");
  const Outcome r =
      run_on_full_disk("good.png", "inspect 'good/" + map.filename().string() + "' --png full/good.png");
  expect_one_line_failure(r, "good.png");
  EXPECT_EQ(slurp(dir / "listing.txt"), "./good.png\n");
  EXPECT_EQ(slurp(dir / "sums.txt"), sums_of("good.png"));
}

}  // namespace
