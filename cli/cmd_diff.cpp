// `shadowlab diff A B`: compares two shadow maps (EXR) or two frames (PNG) pixel by pixel and prints the
// maximum and mean difference, the pixels over the tolerance and, for depth maps, coverage disagreements.
// Exit 0 when no pixel is over the tolerance, 1 when some are, so it can sit in a regression script.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_common.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/material_texture.h"

namespace cli {
namespace {

struct DiffArgs {
  std::string a, b;
  double tolerance = 0.0;
};

// What a comparison found. Per pixel the difference is the largest absolute difference of any channel, in
// the files' [0, 1] units (a PNG byte step is 1/255).
struct DiffResult {
  double max = 0.0, sum = 0.0;
  size_t over = 0, pixels = 0;
  size_t only_a = 0, only_b = 0;  // depth maps: covered (< 1) in one map and not the other

  void add(double d, double tolerance) {
    max = std::max(max, d);
    sum += d;
    over += d > tolerance ? 1 : 0;
  }
};

void check_same_size(const DiffArgs& a, int wa, int ha, int wb, int hb) {
  if (wa != wb || ha != hb)
    throw CliError(a.b, "size " + std::to_string(wb) + "x" + std::to_string(hb) + " differs from " + a.a + " (" +
                            std::to_string(wa) + "x" + std::to_string(ha) + ")");
}

DiffResult diff_maps(const DiffArgs& args) {
  const scenes::io::ExrMap a = scenes::io::read_exr_map(args.a);
  const scenes::io::ExrMap b = scenes::io::read_exr_map(args.b);
  check_same_size(args, a.width, a.height, b.width, b.height);
  DiffResult r;
  r.pixels = a.z.size();
  for (size_t i = 0; i < a.z.size(); ++i) {
    const float za = a.z[i], zb = b.z[i];
    // NaN in either map counts as an infinite difference, never as a match.
    const double d = (std::isnan(za) || std::isnan(zb)) ? INFINITY : std::fabs(double(za) - double(zb));
    r.add(d, args.tolerance);
    const bool ca = za < 1.0f, cb = zb < 1.0f;
    r.only_a += ca && !cb;
    r.only_b += cb && !ca;
  }
  return r;
}

DiffResult diff_frames(const DiffArgs& args) {
  const scenes::io::TextureLoadOptions raw{.srgb = false, .mipmaps = false};  // bytes / 255, unconverted
  const shading::Texture2D a = scenes::io::load_texture(args.a, raw);
  const shading::Texture2D b = scenes::io::load_texture(args.b, raw);
  check_same_size(args, a.width(), a.height(), b.width(), b.height());
  DiffResult r;
  r.pixels = size_t(a.width()) * size_t(a.height());
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const glm::vec4 d = glm::abs(a.texel(x, y) - b.texel(x, y));
      r.add(double(std::max(std::max(d.x, d.y), std::max(d.z, d.w))), args.tolerance);
    }
  return r;
}

int run_diff(const DiffArgs& args) {
  if (!(args.tolerance >= 0.0) || !std::isfinite(args.tolerance))
    throw CliError("--tolerance", "expected a finite number >= 0");
  const std::string ea = lower_extension(args.a), eb = lower_extension(args.b);
  for (const std::string* f : {&args.a, &args.b}) {
    const std::string e = lower_extension(*f);
    if (e != ".exr" && e != ".png") throw CliError(*f, "expected an .exr shadow map or a .png frame");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(*f, ec)) throw CliError(*f, "no such file");
  }
  if (ea != eb) throw CliError(args.b, "cannot compare a " + eb + " file with a " + ea + " file");
  const bool depth = ea == ".exr";
  const DiffResult r = depth ? diff_maps(args) : diff_frames(args);
  const double mean = r.pixels ? r.sum / double(r.pixels) : 0.0;
  std::printf("max %.9g, mean %.9g\n", r.max, mean);
  std::printf("over tolerance %g: %zu of %zu pixels\n", args.tolerance, r.over, r.pixels);
  if (depth) std::printf("covered only in A: %zu, only in B: %zu\n", r.only_a, r.only_b);
  return r.over > 0 ? 1 : 0;
}

}  // namespace

Command add_diff_command(CLI::App& parent) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* app = parent.add_subcommand(
      "diff", "Compare two EXR maps or two PNG frames; exit 1 when a pixel differs by more than the tolerance");
  app->add_option("a", args->a, "First file (.exr or .png)")->required();
  app->add_option("b", args->b, "Second file, same kind and size")->required();
  app->add_option("--tolerance", args->tolerance,
                  "Largest difference allowed per pixel, in [0, 1] units (default 0: exact)");
  return {app, [args] { return run_diff(*args); }};
}

}  // namespace cli
