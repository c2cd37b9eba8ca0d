// `shadowlab diff A B`: compares two depth maps (EXR, the depth channel chosen as `inspect` does) or two frames
// (PNG) and reports the image metrics a script can threshold: max, mean, RMSE, PSNR (OpenImageIO's compare, peak
// 1), the pixels over the tolerance (count and share) and, for depth maps, coverage disagreements. Exit 0 when
// the pixels over the tolerance are within --fail-over (default: none allowed), 1 otherwise; --diff-out writes
// a colour-mapped difference image. Values are in the files' [0, 1] units (a PNG byte step is 1/255).
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <OpenImageIO/imagebufalgo.h>
#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/image_compare.h"
#include "cli/image_input.h"
#include "cli/json_output.h"
#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct DiffArgs {
  std::string a, b, fail_over, diff_out, channel;
  double tolerance = 0.0;
  bool json = false;
};

int run_diff(const DiffArgs& args) {
  if (!(args.tolerance >= 0.0) || !std::isfinite(args.tolerance))
    throw CliError("--tolerance", "expected a finite number >= 0");
  const FailOver fail_over = parse_fail_over(args.fail_over, "--fail-over");
  if (!args.diff_out.empty()) {
    if (lower_extension(args.diff_out) != ".png") throw CliError("--diff-out", "expected a .png file name");
    check_output_dir(args.diff_out, "--diff-out");
  }
  nlohmann::json j = compare_images(args.a, args.b, {args.tolerance, args.channel, args.diff_out});
  const bool failed = over_limit(j, fail_over);
  j["command"] = "diff";
  j["fail_over"] = {{"value", fail_over.value}, {"unit", fail_over.percent ? "percent" : "pixels"}};
  j["failed"] = failed;
  if (args.json) {
    print_json(j);
  } else {
    const double max = j["max"].is_null() ? INFINITY : j["max"].get<double>();
    const double psnr = j["psnr"].is_null() ? INFINITY : j["psnr"].get<double>();
    char psnr_text[64];
    std::snprintf(psnr_text, sizeof psnr_text, "%.6f dB", psnr);
    std::printf("max %.9g, mean %.9g, RMSE %.9g, PSNR %s\n", max, j["mean"].get<double>(), j["rmse"].get<double>(),
                std::isfinite(psnr) ? psnr_text : "inf (identical)");
    if (!j["max_at"].is_null())
      std::printf("largest difference at x %d, y %d (top row 0)\n", j["max_at"][0].get<int>(), j["max_at"][1].get<int>());
    std::printf("over tolerance %g: %zu of %zu pixels (%.6f%%)\n", args.tolerance, j["over"].get<size_t>(),
                j["pixels"].get<size_t>(), j["over_percent"].get<double>());
    if (j["nan_pixels"].get<size_t>())
      std::printf("NaN in either file: %zu pixels (counted as over)\n", j["nan_pixels"].get<size_t>());
    if (j.contains("covered_only_a"))
      std::printf("covered only in A: %zu, only in B: %zu\n", j["covered_only_a"].get<size_t>(),
                  j["covered_only_b"].get<size_t>());
    if (!j["diff_out"].is_null())
      std::printf("difference image: %s (inferno, 0 to %.9g, NaN white)\n", args.diff_out.c_str(),
                  j["diff_out"]["range"][1].get<double>());
    std::printf("%s: at most %g%s allowed over the tolerance\n", failed ? "FAIL" : "pass", fail_over.value,
                fail_over.percent ? "% of the pixels" : " pixels");
  }
  return failed ? 1 : 0;
}

}  // namespace

Command add_diff_command(CLI::App& parent) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* app = parent.add_subcommand(
      "diff", "Compare two EXR depth maps or two PNG frames: max, mean, RMSE, PSNR, pixels over a tolerance; "
              "exit 1 when too many are over");
  app->add_option("a", args->a, "First file (.exr or .png)")->required();
  app->add_option("b", args->b, "Second file, same kind and size")->required();
  app->add_option("--tolerance", args->tolerance,
                  "Largest difference allowed per pixel, in [0, 1] units (default 0: exact)");
  app->add_option("--fail-over", args->fail_over,
                  "Exit 1 only when more than N pixels (or P% of them, e.g. 0.1%) are over the tolerance (default 0)");
  app->add_option("--diff-out", args->diff_out, "Write the per-pixel difference as a colour-mapped PNG (inferno)");
  app->add_option("--channel", args->channel, "EXR depth channel of both maps (default: chosen as inspect does)");
  app->add_flag("--json", args->json, "Print JSON (docs/cli/diff.schema.json) instead of text");
  return {app, [args] { return run_diff(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
