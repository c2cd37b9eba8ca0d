// Runs killed with SIGKILL at every point of their life: a frame and its maps rendered over files that are
// already there, killed at 24 moments spread over the length of a run. Output is deterministic, so after
// every kill each target must hold, byte for byte, either the file that was there or the complete new one; and
// the next run that writes into the folder removes the temporaries a killed run left (scenes/io/atomic_write.h).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/cli_run.h"
#include "tests/support.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

using testsupport::shadowlab;
using testsupport::slurp;

// Starts shadowlab with `args` in `dir`, stdout and stderr discarded; returns its pid.
pid_t spawn_in(const fs::path& dir, const std::vector<std::string>& args) {
  std::vector<std::string> argv_s{SHADOWLAB_CLI};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, SHADOWLAB_CLI, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Every `.NAME.tmp-PID-N.EXT` file under `dir`.
std::vector<fs::path> temporaries(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp-") != std::string::npos) found.push_back(e.path());
  }
  return found;
}

TEST(KilledRun, EveryTargetHoldsTheOldOrTheWholeNewFileAndTheNextRunClearsTheLitter) {
  const fs::path dir = testsupport::temp_dir("killed_run");
  const std::vector<std::string> outputs{"frame.png", "maps/light0-sun.exr"};
  // The old files (a small render) and the new ones (the large render the killed runs attempt), both made by
  // runs that finish, in a separate folder so the new ones never appear in `dir` except by a killed run.
  const fs::path ref = dir / "ref";
  fs::create_directories(ref);
  ASSERT_EQ(shadowlab(ref, "render tutorial --size 1024x768 --shadow-size 2048 --out frame.png --maps maps").code, 0);
  std::vector<std::string> fresh;
  for (const auto& o : outputs) fresh.push_back(slurp(ref / o));
  const fs::path work = dir / "work";
  fs::create_directories(work);
  ASSERT_EQ(shadowlab(work, "render tutorial --size 64x48 --shadow-size 64 --out frame.png --maps maps").code, 0);
  std::vector<std::string> old;
  for (const auto& o : outputs) old.push_back(slurp(work / o));
  for (size_t i = 0; i < outputs.size(); ++i) ASSERT_NE(old[i], fresh[i]) << outputs[i];

  const std::vector<std::string> args{"render", "tutorial", "--size", "1024x768", "--shadow-size", "2048",
                                      "--out",  "frame.png", "--maps", "maps"};
  // A run's length, measured here (it varies with the machine and its load); the kills fall at 24 points
  // spread over it, from the start (loading) to the end (encoding, writing, renaming).
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(shadowlab(ref, "render tutorial --size 1024x768 --shadow-size 2048 --out again.png").code, 0);
  const double run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  constexpr int kAttempts = 24;
  int kills = 0, replaced = 0;
  for (int k = 0; k < kAttempts; ++k) {
    // Put the old files back, so every attempt starts from them.
    for (size_t i = 0; i < outputs.size(); ++i) {
      if (slurp(work / outputs[i]) != old[i]) {
        std::ofstream(work / outputs[i], std::ios::binary | std::ios::trunc) << old[i];
      }
    }
    const auto delay = std::chrono::microseconds(int64_t(run_ms * 1000.0 * (k + 0.5) / kAttempts));
    const pid_t pid = spawn_in(work, args);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(delay);
    ::kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    const bool killed = WIFSIGNALED(status);
    if (killed) {
      ++kills;
    } else {
      ASSERT_TRUE(WIFEXITED(status));
      ASSERT_EQ(WEXITSTATUS(status), 0);
    }
    for (size_t i = 0; i < outputs.size(); ++i) {
      const std::string now = slurp(work / outputs[i]);
      EXPECT_TRUE(now == old[i] || now == fresh[i])
          << outputs[i] << " damaged by a kill after " << delay.count() / 1000 << " ms of " << run_ms;
      if (now == fresh[i] && killed) ++replaced;
    }
    if (::testing::Test::HasFailure()) return;
  }
  // Most kills land inside a run (a quarter at least, allowing for a load that changes while the test runs), or
  // the test would prove nothing.
  EXPECT_GE(kills, kAttempts / 4);
  std::cout << "[ killed ] " << kills << " of " << kAttempts << " runs over " << run_ms << " ms; " << replaced
            << " targets already replaced when killed\n";
  // A run that finishes removes what the killed ones left.
  ASSERT_EQ(shadowlab(work, "render tutorial --size 1024x768 --shadow-size 2048 --out frame.png --maps maps").code, 0);
  EXPECT_TRUE(temporaries(work).empty()) << temporaries(work).front();
  for (size_t i = 0; i < outputs.size(); ++i) EXPECT_EQ(slurp(work / outputs[i]), fresh[i]) << outputs[i];
}

}  // namespace
