// Comparing two images the way `diff` and `check` do: two depth maps (EXR, depth channel chosen as `inspect`
// does) or two frames (PNG), with OpenImageIO's metrics (max, mean, RMSE, PSNR with peak 1, pixels with some
// channel over the tolerance), NaN differences counted apart and always over, coverage disagreements for maps,
// and an optional colour-mapped difference image. Values are in the files' [0, 1] units.
#pragma once
#include <string>

#include <nlohmann/json.hpp>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

struct CompareOptions {
  double tolerance = 0.0;  // largest difference per pixel that is not "over"
  std::string channel;     // EXR depth channel (empty: chosen)
  std::string diff_out;    // PNG to write the difference to (empty: none)
};

// The comparison as the fields of `diff --json` (a, b, kind, channels, width, height, pixels, max, max_at, mean,
// rmse, psnr, nan_pixels, tolerance, over, over_percent, covered_only_a/b for maps, diff_out). Throws CliError
// naming the file for unreadable files, different kinds, sizes or channel counts.
nlohmann::json compare_images(const std::string& a, const std::string& b, const CompareOptions& options);

// How many pixels over the tolerance still pass: N pixels, or P% of them.
struct FailOver {
  double value = 0.0;
  bool percent = false;
};
// "N" or "P%" (empty: 0 pixels); anything else is a CliError on `where`.
FailOver parse_fail_over(const std::string& text, const std::string& where);
// Whether a comparison's pixels over the tolerance exceed `limit`.
bool over_limit(const nlohmann::json& result, const FailOver& limit);

SHADOWLAB_ISA_END
}  // namespace cli
