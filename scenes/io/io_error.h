// The one exception type of file I/O: what() reads "FILE: what is wrong", which the CLI prints after
// "shadowlab: error: ". Everything in scenes/io throws it, whatever library failed underneath.
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

class IoError : public std::runtime_error {
 public:
  IoError(const std::filesystem::path& file, const std::string& reason)
      : std::runtime_error(file.string() + ": " + reason), file_(file), reason_(reason) {}

  const std::filesystem::path& file() const { return file_; }
  const std::string& reason() const { return reason_; }

 private:
  std::filesystem::path file_;
  std::string reason_;
};

SHADOWLAB_ISA_END
}  // namespace scenes::io
