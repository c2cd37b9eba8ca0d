// EXR files encoded in memory, then written with write_bytes (atomic_write.h), which checks every write, the
// flush and the close. OpenEXR's own file stream writes through std::ofstream and drops the error of its last
// flush in a destructor: on a full disk a small map came out as a 0-byte file and the run exited 0.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <OpenEXR/ImfIO.h>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

// An Imf::OStream into a growing byte buffer (OpenEXR seeks back to fill in its line offset table).
class ExrMemoryStream : public Imf::OStream {
 public:
  ExrMemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override;
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = pos; }
  // Writes the bytes to `path` through write_bytes (IoError naming `path` on any failure).
  void save(const std::filesystem::path& path) const;
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
  uint64_t position_ = 0;
};

SHADOWLAB_ISA_END
}  // namespace scenes::io
