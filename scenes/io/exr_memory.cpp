// The in-memory EXR stream (see exr_memory.h).
#include "scenes/io/exr_memory.h"

#include <cstring>

#include "scenes/io/atomic_write.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

void ExrMemoryStream::write(const char c[], int n) {
  if (n <= 0) return;
  const uint64_t end = position_ + uint64_t(n);
  if (end > bytes_.size()) bytes_.resize(size_t(end));
  std::memcpy(bytes_.data() + position_, c, size_t(n));
  position_ = end;
}

void ExrMemoryStream::save(const std::filesystem::path& path) const { write_bytes(path, bytes_.data(), bytes_.size()); }

SHADOWLAB_ISA_END
}  // namespace scenes::io
