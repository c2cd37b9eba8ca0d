// The images users hand to `inspect`, `diff` and `check`: shadowlab's own maps, EXRs from other renderers
// (Blender's `ViewLayer.Depth.Z`, oiiotool's `R` or `Y`, a bare `depth.Z`) and PNG frames. Which channel of an
// EXR holds depth is chosen here, by one rule, and said aloud.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// The kinds of file the commands read, by extension.
enum class ImageKind { exr, png };
// .exr or .png (any case); anything else is a CliError on `file`. A missing file is a CliError too.
ImageKind image_kind(const std::string& file);

// The depth channel of an EXR and why it was chosen.
struct ChannelChoice {
  std::string name;
  std::string reason;  // "asked for", "the only channel", "named Z", "a depth layer's Z", "red", "luminance"
};

// `requested` when given (it must exist); otherwise the only channel, else `Z`, else the first channel whose
// name ends in `.Z` (`depth.Z`, `ViewLayer.Depth.Z`), else `R`, else `Y`. None of these: a CliError on `file`
// listing the channels and pointing at --channel.
ChannelChoice choose_depth_channel(const std::vector<std::string>& channels, const std::string& requested,
                                   const std::string& file);

// A whole image through OpenImageIO as float pixels (PNG bytes / 255, unconverted: the file's own sRGB values),
// top row first; `file_bits`, when given, receives the bits per sample the file stores (8 for shadowlab's PNGs).
// Throws CliError naming the file when it cannot be read.
OIIO::ImageBuf read_image(const std::string& file, int* file_bits = nullptr);

SHADOWLAB_ISA_END
}  // namespace cli
