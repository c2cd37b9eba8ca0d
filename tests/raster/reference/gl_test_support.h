// Helpers for the tests that use the llvmpipe reference: make a Context or skip the test with the reason, and
// count llvmpipe's rasterizer threads (named "llvmpipe-N") in this process.
#pragma once
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "raster/reference/gl_reference.h"
#include "tests/support.h"

// Declares `std::unique_ptr<glref::Context> name` with `threads` rasterizer threads, or skips the test.
#define GLREF_CONTEXT_OR_SKIP(name, threads)                   \
  std::string name##_why;                                      \
  auto name = glref::Context::create((threads), &name##_why);  \
  if (!name) GTEST_SKIP() << "skipped: " << name##_why

namespace testsupport {

// Threads for the reference: SHADOWLAB_TEST_THREADS like the pipeline tests, else 2.
inline int glref_threads() {
  if (std::getenv("SHADOWLAB_TEST_THREADS")) return test_threads();
  return 2;
}

inline int llvmpipe_thread_count() {
  int n = 0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    std::getline(comm, name);
    if (name.rfind("llvmpipe-", 0) == 0) ++n;
  }
  return n;
}

// llvmpipe's workers name themselves after they start and leave /proc a moment after they are joined, so on a
// loaded machine the count lags the context: poll until it reaches `expected` or 10 s pass, then return it.
inline int llvmpipe_thread_count_settled(int expected) {
  int n = llvmpipe_thread_count();
  for (int i = 0; i < 1000 && n != expected; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    n = llvmpipe_thread_count();
  }
  return n;
}

}  // namespace testsupport
