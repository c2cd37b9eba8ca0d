// Output names of `render` jobs: `{scene}` becomes the scene's name (a built-in's name, a file's stem, made safe
// for file names) and one printf frame field (`%d`, `%04d`) becomes the frame number (1 for the first frame), so
// batches and image sequences write one file each: `out/{scene}.png`, `seq/frame_%04d.png`.
#pragma once
#include <string>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// The scene part of file names for scene argument `scene` (a built-in name or a file path).
std::string scene_stem(const std::string& scene);

// Whether `pattern` holds a frame field; more than one, or a `%` that starts no field (write `%%` for '%'), is
// a CliError on `option`.
bool has_frame_field(const std::string& pattern, const std::string& option);
// Whether `pattern` holds `{scene}`.
bool has_scene_field(const std::string& pattern);

// `pattern` with `{scene}` and the frame field filled in (`%%` becomes '%').
std::string expand_name(const std::string& pattern, const std::string& stem, int frame);

SHADOWLAB_ISA_END
}  // namespace cli
