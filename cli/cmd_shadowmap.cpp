// `shadowlab shadowmap`: one depth pass of every triangle of a scene file with exactly the light matrices a
// user gives, written as an EXR map, so a shadow map an engine made can be reproduced and compared. With
// --repeat it also times the pass alone (clear + draw, after a warm-up) and prints the median and minimum.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/light_matrix.h"
#include "raster/renderer.h"
#include "raster/shader.h"
#include "raster/state.h"
#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "scenes/scene_build.h"
#include "scenes/scene_queries.h"
#include "scenes/shadow_settings.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

// World-space positions in, clip space out through one light matrix: the depth-only path of the pipeline.
struct WorldDepthShader {
  using Vertex = glm::vec3;
  using Varyings = raster::NoVaryings;
  glm::mat4 view_proj{1.0f};
  glm::vec4 vertex(const Vertex& p, Varyings&) const { return view_proj * glm::vec4(p, 1.0f); }
};

struct ShadowmapArgs {
  std::string scene, light_matrix, size, format, cull = "none", offset, out;
  std::optional<int> threads;  // --threads, left out for all cores
  int repeat = 0;
};

int run_shadowmap(const ShadowmapArgs& a) {
  // Every option is checked before any file is read, so the cheapest mistakes are reported first.
  const Size2 size = parse_size(a.size, "--size");
  const auto format = raster::parse_depth_format(a.format);
  if (!format)
    throw CliError("--format", "unknown depth format '" + a.format + "' (known: " +
                                   scenes::join_names(scenes::depth_format_names()) + ")");
  const auto cull = raster::parse_cull_mode(a.cull);
  if (!cull) throw CliError("--cull", "unknown cull mode '" + a.cull + "' (known: none, back, front)");
  raster::DrawState state;
  state.cull = *cull;
  if (!a.offset.empty()) {
    const auto [factor, units] = parse_float_pair(a.offset, "--offset", "FACTOR,UNITS");
    state.polygon_offset = {factor, units};
  }
  check_threads(a.threads);
  if (lower_extension(a.out) != ".exr") throw CliError("--out", "expected an .exr file name");
  check_output_dir(a.out, "--out");
  if (a.repeat < 0) throw CliError("--repeat", "expected a count of 0 or more");

  const LightMatrices light = read_light_matrices(a.light_matrix);
  scenes::Scene scene = [&] {
    const std::filesystem::path path(a.scene);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw CliError(a.scene, "no such file");
    return scenes::load_scene(path);
  }();
  const scenes::TriangleSoup soup = scenes::flatten(scene, scenes::InstanceFilter::all);
  if (soup.triangle_count() == 0) throw CliError(a.scene, "the scene has no triangles");
  scene = {};  // only the soup is needed from here on

  raster::Renderer renderer(check_threads(a.threads));
  raster::DepthTarget target(size.width, size.height, *format);
  const WorldDepthShader shader{light.view_proj};
  const auto pass = [&] {
    target.clear(1.0f);
    return renderer.draw(raster::RenderTargets{&target, nullptr}, state, shader,
                         std::span<const glm::vec3>(soup.positions), std::span<const uint32_t>(soup.indices));
  };

  pass();  // warm-up (and the result when not timing)
  if (a.repeat > 0) {
    Progress progress;
    std::vector<double> times;
    times.reserve(size_t(a.repeat));
    for (int i = 0; i < a.repeat; ++i) {
      progress.update("pass " + std::to_string(i + 1) + "/" + std::to_string(a.repeat));
      const Stopwatch watch;
      pass();
      times.push_back(watch.ms());
    }
    std::sort(times.begin(), times.end());
    const size_t n = times.size();
    const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
    std::printf("median %.3f ms, min %.3f ms (%d passes, %zu triangles, %dx%d %s)\n", median, times.front(),
                a.repeat, soup.triangle_count(), size.width, size.height, a.format.c_str());
  }

  scenes::io::ExrMap map = scenes::io::exr_map_from(target);
  map.world_to_camera = light.view;
  map.world_to_ndc = light.view_proj;
  map.technique = "shadowmap";
  map.encoding = "window-depth";
  scenes::io::write_exr_map(a.out, map);
  return 0;
}

}  // namespace

Command add_shadowmap_command(CLI::App& parent) {
  auto args = std::make_shared<ShadowmapArgs>();
  CLI::App* app = parent.add_subcommand(
      "shadowmap", "One depth pass of every triangle of a scene file with given light matrices, written as EXR");
  app->add_option("--scene", args->scene, "Scene file: JSON, .gltf or .glb")->required();
  app->add_option("--light-matrix", args->light_matrix,
                  "JSON file: {\"view\": [16], \"proj\": [16]} or {\"view_proj\": [16]}, glm::value_ptr order")
      ->required();
  app->add_option("--size", args->size, "Map size WIDTHxHEIGHT")->required();
  app->add_option("--format", args->format, "Depth format: d16, d24 or d32f")->required();
  app->add_option("--cull", args->cull, "Face culling: none, back or front (default none)");
  app->add_option("--offset", args->offset, "Polygon offset FACTOR,UNITS as glPolygonOffset takes them");
  add_threads_option(*app, args->threads);
  app->add_option("--repeat", args->repeat, "Time the pass N times after a warm-up; prints median and min");
  app->add_option("--out", args->out, "Output EXR file")->required();
  return {app, [args] { return run_shadowmap(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
