// Helpers for the tests that use the llvmpipe reference: make a Context or skip the test with the reason, and
// count llvmpipe's rasterizer threads (named "llvmpipe-N") in this process.
#pragma once
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/gl/gl_reference.h"
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

}  // namespace testsupport
