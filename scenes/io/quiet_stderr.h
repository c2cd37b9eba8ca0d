// QuietStderr: sends stderr to /dev/null while it lives. libpng (inside OpenImageIO) prints its own "libpng
// error: ..." line on a broken file before OpenImageIO returns the same error to the caller, which reports it
// once, in one line (every error of shadowlab is one line).
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ >= 0) ::dup2(saved_, 2), ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

SHADOWLAB_ISA_END
}  // namespace scenes::io
