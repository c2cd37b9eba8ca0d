// `shadowlab render SCENE`: a whole frame (every light's shadow maps, then the shaded camera view) through
// cli/frame, written as a PNG, with every shadow map as EXR on request and per-frame statistics with --stats.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_common.h"
#include "scenes/builtin_scenes.h"
#include "scenes/shadow_settings.h"
#ifdef SHADOWLAB_HAVE_FRAME
#include "cli/frame/frame.h"
#include "cli/frame/frame_omni.h"
#include "raster/renderer.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#endif

namespace cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string technique, filter, bias, size = "1280x720", maps, out = "frame.png";
  long long shadow_size = 0;
  CLI::Option* shadow_size_option = nullptr;  // given or not
  int threads = -1;
  int frames = 1;
  bool stats = false;
  std::optional<bool> cull_front;  // --cull-front / --no-cull-front
  int poisson_taps = 0;            // 0: the light's setting
  std::optional<bool> pcf_taps;    // --pcf-taps / --no-pcf-taps
  std::string projective_mode;              // --projective-mode; empty: the light's setting
  std::optional<int> projective_textures;   // --projective-textures
  bool animate = false;                     // --animate: rebuild an animated built-in scene per frame
  double fps = 24.0;                        // --fps: frame K is at time K / fps
  std::string stratify, fit;
  std::optional<bool> seamless;               // --seamless / --no-seamless (cube)
  std::string paraboloid_pack, split_plane;  // paraboloid: float | rgba8; light | x | -y | ... | a,b,c
  // Value overrides, set only when given on the command line.
  std::optional<float> poisson_spread, bias_constant, bias_slope, bias_slope_max, offset_factor, offset_units,
      normal_offset;
};

// A float option that stays unset unless given (CLI11 checks that the text is a number).
void add_value(CLI::App* app, const char* name, std::optional<float>& target, const char* help) {
  app->add_option_function<float>(name, [&target](const float& v) { target = v; }, help);
}

// An override's name is checked against the scene module's table before anything is loaded.
void check_name(const std::string& value, const std::string& option, const char* what, bool known,
                std::span<const scenes::NamedEntry> table) {
  if (!value.empty() && !known)
    throw CliError(option, std::string("unknown ") + what + " '" + value + "' (known: " + scenes::join_names(table) +
                               ")");
}

int run_render(const RenderArgs& a) {
  const Size2 size = parse_size(a.size, "--size");
  check_name(a.technique, "--technique", "technique", scenes::parse_technique(a.technique).has_value(),
             scenes::technique_names());
  check_name(a.filter, "--filter", "filter", scenes::parse_filter(a.filter).has_value(), scenes::filter_names());
  check_name(a.bias, "--bias", "bias mode", scenes::parse_bias_mode(a.bias).has_value(), scenes::bias_mode_names());
  if (a.poisson_taps != 0 && a.poisson_taps != 4 && a.poisson_taps != 16)
    throw CliError("--poisson-taps", std::to_string(a.poisson_taps) + " is not 4 or 16");
  const std::optional<int> shadow_size =
      a.shadow_size_option->count() ? std::optional<int>(check_side(a.shadow_size, "--shadow-size")) : std::nullopt;
  if (a.threads < -1) throw CliError("--threads", "expected 0 or more threads");
  if (a.frames < 1) throw CliError("--frames", "expected 1 or more frames");
  if (!a.projective_mode.empty() && a.projective_mode != "multipass" && a.projective_mode != "single-pass")
    throw CliError("--projective-mode", "unknown mode '" + a.projective_mode + "' (known: multipass, single-pass)");
  if (a.projective_textures && (*a.projective_textures < 1 || *a.projective_textures > 8))
    throw CliError("--projective-textures", std::to_string(*a.projective_textures) + " is outside 1..8");
  if (a.animate) {
    if (!std::isfinite(a.fps) || !(a.fps > 0.0)) throw CliError("--fps", "expected a frame rate above 0");
    bool animated = false;
    std::error_code ec;
    if (!std::filesystem::exists(a.scene, ec))
      for (const scenes::BuiltinInfo& b : scenes::list_builtin_scenes()) animated |= b.name == a.scene && b.animated;
    if (!animated) throw CliError("--animate", "'" + a.scene + "' is not an animated built-in scene (animated: projective)");
  }
  if (!a.paraboloid_pack.empty() && a.paraboloid_pack != "float" && a.paraboloid_pack != "rgba8")
    throw CliError("--paraboloid-pack", "unknown value '" + a.paraboloid_pack + "' (known: float, rgba8)");
  if (lower_extension(a.out) != ".png") throw CliError("--out", "expected a .png file name");
  check_output_dir(a.out, "--out");
  if (!a.maps.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(a.maps, ec) && !std::filesystem::is_directory(a.maps, ec))
      throw CliError("--maps", a.maps + " exists and is not a directory");
  }

  scenes::Scene scene = load_scene_or_builtin(a.scene);
#ifndef SHADOWLAB_HAVE_FRAME
  (void)scene, (void)size, (void)shadow_size;
  throw CliError("render", "this build of shadowlab has no frame renderer (cli/frame was not built)");
#else
  frame::FrameOptions options;
  options.width = size.width;
  options.height = size.height;
  if (!a.technique.empty()) options.technique = a.technique;
  if (!a.filter.empty()) options.filter = a.filter;
  if (!a.bias.empty()) options.bias = a.bias;
  options.shadow_size = shadow_size;
  options.cull_front = a.cull_front;
  options.pcf_taps = a.pcf_taps;
  if (a.poisson_taps != 0) options.poisson_taps = a.poisson_taps;
  if (!a.stratify.empty()) options.stratify = a.stratify;
  if (!a.fit.empty()) options.fit = a.fit;
  options.poisson_spread = a.poisson_spread;
  options.bias_constant = a.bias_constant;
  options.bias_slope = a.bias_slope;
  options.bias_slope_max = a.bias_slope_max;
  options.offset_factor = a.offset_factor;
  options.offset_units = a.offset_units;
  options.normal_offset = a.normal_offset;
  if (!a.projective_mode.empty()) options.projective_mode = a.projective_mode;
  options.projective_textures = a.projective_textures;
  options.export_maps = !a.maps.empty();  // projective maps become EXR records only when written
  options.seamless = a.seamless;
  if (!a.paraboloid_pack.empty()) options.paraboloid_pack = a.paraboloid_pack;
  if (!a.split_plane.empty()) {
    if (a.split_plane != "light" && !frame::parse_split_plane(a.split_plane))
      throw CliError("--split-plane", "'" + a.split_plane + "' is not light, x, y, z, -x, -y, -z or a non-zero normal a,b,c");
    options.split_plane = a.split_plane;
  }

  raster::Renderer renderer(a.threads);
  Progress progress;
  std::optional<frame::Frame> result;  // Frame has no empty state: the last frame rendered
  frame::FrameCache cache;             // projective maps live across frames: only changed casters are rebuilt
  for (int i = 0; i < a.frames; ++i) {
    if (a.animate && i > 0) scene = scenes::builtin_scene(a.scene, {double(i) / a.fps});
    if (a.frames > 1) progress.update("frame " + std::to_string(i + 1) + "/" + std::to_string(a.frames));
    const Stopwatch watch;
    result.emplace(frame::render_frame(scene, options, renderer, &cache));
    const double total = watch.ms();
    if (a.stats) {
      const frame::FrameStats& s = result->stats;
      std::printf(
          "frame %d: total %.3f ms, shadow %.3f ms, camera %.3f ms, maps %zu, triangles %llu, setups %llu, "
          "clipped %llu, culled %llu, rejected %llu\n",
          i + 1, total, s.shadow_ms, s.camera_ms, s.maps_rendered, (unsigned long long)s.draws.triangles,
          (unsigned long long)s.draws.setups, (unsigned long long)s.draws.clipped,
          (unsigned long long)s.draws.culled, (unsigned long long)s.draws.rejected);
      if (s.projective.active)
        std::printf("frame %d: maps rebuilt %zu, reused %zu\n", i + 1, s.projective.maps_rebuilt,
                    s.projective.maps_reused);
    }
  }

  if (!a.maps.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.maps, ec);
    if (ec) throw CliError("--maps", "cannot create directory " + a.maps + " (" + ec.message() + ")");
    for (size_t m = 0; m < result->maps.size(); ++m) {
      const std::string name = m < result->map_names.size() ? result->map_names[m] : "map" + std::to_string(m);
      scenes::io::write_exr_map(std::filesystem::path(a.maps) / (name + ".exr"), result->maps[m]);
    }
  }
  scenes::io::write_png(a.out, result->color);
  return 0;
#endif
}

}  // namespace

Command add_render_command(CLI::App& parent) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* app = parent.add_subcommand("render", "Render a scene: shadow maps, then the shaded camera view");
  app->add_option("scene", args->scene, "Scene: a JSON file, a .gltf/.glb file, or a built-in name (see list)")
      ->required();
  app->add_option("--technique", args->technique, "Shadow technique for every light (see list)");
  app->add_option("--filter", args->filter, "Shadow filter for every light (see list)");
  app->add_option("--bias", args->bias, "Bias mode for every light (see list)");
  app->add_option("--size", args->size, "Frame size WIDTHxHEIGHT (default 1280x720)");
  args->shadow_size_option = app->add_option("--shadow-size", args->shadow_size, "Shadow map side in texels");
  app->add_option("--threads", args->threads, "Worker threads (0: inline; default: all cores)");
  app->add_option("--frames", args->frames, "Render the frame N times (timing); the last one is written");
  app->add_flag("--stats", args->stats, "Print per-frame timings and triangle counts");
  app->add_option("--out", args->out, "Output PNG (default frame.png)");
  app->add_flag_callback("--cull-front", [args] { args->cull_front = true; }, "Render only back faces into the maps");
  app->add_flag_callback("--no-cull-front", [args] { args->cull_front = false; }, "Render front faces into the maps");
  app->add_option("--poisson-taps", args->poisson_taps, "Poisson filters: 4 or 16 taps");
  app->add_flag_callback("--pcf-taps", [args] { args->pcf_taps = true; }, "Poisson taps are hardware-PCF lookups");
  app->add_flag_callback("--no-pcf-taps", [args] { args->pcf_taps = false; }, "Poisson taps are single compares");
  app->add_option("--stratify", args->stratify, "Stratified Poisson seed: pixel or world (position rounded to 1 mm)");
  app->add_option("--fit", args->fit, "Directional light box: auto (fitted to receivers and casters) or fixed");
  RenderArgs& r = *args;
  add_value(app, "--poisson-spread", r.poisson_spread, "Poisson disc radius in map texture coordinates (1/700)");
  add_value(app, "--bias-constant", r.bias_constant, "constant bias: window depth subtracted (0.005)");
  add_value(app, "--bias-slope", r.bias_slope, "slope bias: scale of tan(acos(N.L)) (0.005)");
  add_value(app, "--bias-slope-max", r.bias_slope_max, "slope bias: upper clamp (0.01)");
  add_value(app, "--offset-factor", r.offset_factor, "offset bias: glPolygonOffset factor (1.1)");
  add_value(app, "--offset-units", r.offset_units, "offset bias: glPolygonOffset units (4)");
  add_value(app, "--normal-offset", r.normal_offset, "normal bias: receiver moved along its normal, metres (0.02)");
  app->add_flag_callback("--seamless", [args] { args->seamless = true; }, "Cube maps: seamless filtering (default)");
  app->add_flag_callback("--no-seamless", [args] { args->seamless = false; }, "Cube maps: each face filtered alone");
  app->add_option("--paraboloid-pack", args->paraboloid_pack,
                  "Paraboloid depth storage: float (default) or rgba8 (base-256 pack into an RGBA8 target)");
  app->add_option("--split-plane", args->split_plane,
                  "Paraboloid split plane normal: light (its direction, default), x, y, z, -x, -y, -z or a,b,c");
  app->add_option("--maps", args->maps, "Also write every shadow map as DIR/<map name>.exr");
  app->add_option("--projective-mode", args->projective_mode,
                  "Projective shadows: multipass (a multiply pass per caster) or single-pass");
  app->add_option_function<int>(
      "--projective-textures", [args](const int& v) { args->projective_textures = v; },
      "Projective single-pass: shadow textures per draw, 1..8 (more casters: extra passes)");
  app->add_flag("--animate", args->animate, "Animated built-in scenes (projective): frame K at time K / fps");
  app->add_option("--fps", args->fps, "Frame rate of --animate (default 24)");
  return {app, [args] { return run_render(*args); }};
}

}  // namespace cli
