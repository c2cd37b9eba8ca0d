// `shadowlab inspect MAP.exr`: what a shadow-map file holds — size, channel, depth range, coverage, the
// header's technique, format, encoding and matrices (and per-pass data) — plus an optional false-colour PNG.
#include <cstdio>
#include <memory>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "cli/cli_common.h"
#include "cli/map_stats.h"
#include "raster/limits.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"

namespace cli {
namespace {

// A matrix as the 16 values in glm::value_ptr order, the layout light matrix files use (so it can be pasted).
void print_matrix(const char* label, const glm::mat4& m) {
  const float* v = glm::value_ptr(m);
  std::printf("%s: [", label);
  for (int i = 0; i < 16; ++i) std::printf("%s%.9g", i ? ", " : "", double(v[i]));
  std::printf("]\n");
}

std::string or_unset(const std::string& s) { return s.empty() ? "(unset)" : s; }

struct InspectArgs {
  std::string map, png;
};

int run_inspect(const InspectArgs& a) {
  if (!a.png.empty() && lower_extension(a.png) != ".png") throw CliError("--png", "expected a .png file name");
  if (!a.png.empty()) check_output_dir(a.png, "--png");
  const scenes::io::ExrMap map = scenes::io::read_exr_map(a.map);
  const MapStats s = map_stats(map);
  std::printf("file: %s\n", a.map.c_str());
  std::printf("size: %dx%d\n", map.width, map.height);
  std::printf("channels: Z\n");
  std::printf("technique: %s\n", or_unset(map.technique).c_str());
  std::printf("depth format: %s\n", or_unset(map.depth_format).c_str());
  std::printf("encoding: %s\n", or_unset(map.encoding).c_str());
  std::printf("depth: min %.9g, max %.9g\n", double(s.min), double(s.max));
  if (s.covered)
    std::printf("covered depth: min %.9g, max %.9g\n", double(s.covered_min), double(s.covered_max));
  std::printf("coverage: %.6f (%zu of %zu texels < 1)\n", s.coverage(), s.covered, s.texels);
  print_matrix("worldToCamera", map.world_to_camera);
  print_matrix("worldToNDC", map.world_to_ndc);
  std::printf("passes: %zu\n", map.passes.size());
  for (size_t i = 0; i < map.passes.size(); ++i) {
    const scenes::io::MapPass& p = map.passes[i];
    std::printf("pass %zu: label %s, viewport %d %d %d %d\n", i, or_unset(p.label).c_str(), p.viewport.x,
                p.viewport.y, p.viewport.width, p.viewport.height);
    print_matrix(("pass " + std::to_string(i) + " worldToCamera").c_str(), p.world_to_camera);
    print_matrix(("pass " + std::to_string(i) + " worldToNDC").c_str(), p.world_to_ndc);
  }
  if (!a.png.empty()) {
    // A map from elsewhere may exceed what a frame target holds (issue 23: 16385 x 1 failed with the target's
    // internal wording).
    if (map.width > raster::kMaxTargetSize || map.height > raster::kMaxTargetSize)
      throw CliError("--png", "a preview of a " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                                  " map is larger than " + std::to_string(raster::kMaxTargetSize) +
                                  " pixels a side; the statistics above are complete");
    scenes::io::write_png(a.png, false_colour(map, s));
    std::printf("preview: %s\n", a.png.c_str());
  }
  return 0;
}

}  // namespace

Command add_inspect_command(CLI::App& parent) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* app = parent.add_subcommand("inspect", "Describe a shadow-map EXR file and optionally preview it");
  app->add_option("map", args->map, "Shadow map (.exr)")->required();
  app->add_option("--png", args->png, "Write a false-colour preview PNG (uncovered texels black)");
  return {app, [args] { return run_inspect(*args); }};
}

}  // namespace cli
