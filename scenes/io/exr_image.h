// Multi-channel float images as EXR files: named FLOAT channels of one size, in GL row order in memory (row 0 the
// bottom), written top row first as CONVENTIONS.md asks so that they align with the PNG frame. Used for the
// camera pass's per-pixel surface record (`shadowlab render --aov`); shadow maps have their own format (exr_map.h).
#pragma once
#include <filesystem>
#include <string>
#include <vector>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

struct ExrChannel {
  std::string name;
  std::vector<float> values;  // width · height, index y · width + x, row 0 at the bottom
};

struct ExrImage {
  int width = 0, height = 0;
  std::vector<ExrChannel> channels;
  // The channel named `name`, or null.
  const ExrChannel* find(const std::string& name) const;
};

// Writes every channel as FLOAT (ZIP compression) through a temporary file. Throws IoError naming `path` for an
// empty size, a channel of the wrong length, a duplicate or empty channel name, or a failed write.
void write_exr_image(const std::filesystem::path& path, const ExrImage& image);
// The same, staged in `batch` (atomic_write.h): it replaces `path` when the batch commits.
class WriteBatch;
void write_exr_image(WriteBatch& batch, const std::filesystem::path& path, const ExrImage& image);

// Reads every channel of an EXR file as floats. Throws IoError naming `path`.
ExrImage read_exr_image(const std::filesystem::path& path);

SHADOWLAB_ISA_END
}  // namespace scenes::io
