// Helpers shared by the tests: where the assets are, the thread count to use, temporary directories.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace testsupport {

inline std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("SHADOWLAB_ASSETS")) return env;
  return SHADOWLAB_ASSETS_DIR;
}

inline bool have_assets() { return std::filesystem::exists(assets_dir() / "README.md"); }

// Threads for pipeline tests: SHADOWLAB_TEST_THREADS, else the hardware's.
inline int test_threads() {
  if (const char* env = std::getenv("SHADOWLAB_TEST_THREADS")) return std::atoi(env);
  return int(std::thread::hardware_concurrency());
}

// A fresh, empty directory under the build tree for one test's files.
inline std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::path(SHADOWLAB_BINARY_DIR) / "test-tmp" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace testsupport

// Skips the current test when ../shared/assets is absent, with the message the project promises.
#define SHADOWLAB_REQUIRE_ASSETS()                                   \
  do {                                                               \
    if (!testsupport::have_assets()) {                               \
      GTEST_SKIP() << "skipped: ../shared/assets not found";         \
    }                                                                \
  } while (0)
