// PNG frames: a colour target written as 8-bit sRGB through OpenImageIO, top row first (the target's row 0,
// the bottom of the frame, is the file's last row).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include "raster/target.h"
#include "scenes/io/atomic_write.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

// The frame as 8-bit sRGB bytes, top row first, 3 (RGB) or 4 (RGBA) bytes per pixel. An sRGB RGBA8 target's
// bytes are taken as they are; a linear RGBA8 or an RGBA32F target is clamped to [0, 1] and sRGB-encoded
// (alpha stays linear), then rounded to the nearest byte.
std::vector<uint8_t> srgb8_top_first(const raster::ColorTarget& target, bool alpha = false);

// srgb8_top_first(target, alpha) encoded as a PNG file's bytes, in memory. `name` is for errors (IoError).
std::vector<unsigned char> encode_png(const raster::ColorTarget& target, bool alpha, const std::filesystem::path& name);

// Writes srgb8_top_first(target, alpha) as a PNG through a temporary file. Throws IoError.
void write_png(const std::filesystem::path& path, const raster::ColorTarget& target, bool alpha = false);
// The same, staged in `batch` (it replaces `path` when the batch commits).
void write_png(WriteBatch& batch, const std::filesystem::path& path, const raster::ColorTarget& target,
               bool alpha = false);

SHADOWLAB_ISA_END
}  // namespace scenes::io
