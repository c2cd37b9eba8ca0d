// `shadowlab render SCENE`: a whole frame through the scenes/frame library, written as a PNG, with every shadow
// map as EXR on request and per-frame statistics with --stats. This file only turns arguments into a
// frame::FrameConfig: the technique parameters' options come from the vocabulary's ParamSpec lists.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_common.h"
#include "raster/renderer.h"
#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "scenes/io/exr_image.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#include "scenes/shadow_settings.h"

namespace cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string technique, filter, bias, depth_format, size = "1280x720", maps, out = "frame.png", aliasing;
  std::string aov, aov_out;  // --aov position,normal,visibility,depth  --aov-out FILE.exr
  long long shadow_size = 0;
  CLI::Option* shadow_size_option = nullptr;  // given or not
  int threads = -1;
  int frames = 1;
  bool stats = false;
  std::optional<bool> cull_front;  // --cull-front / --no-cull-front
  int poisson_taps = 0;            // 0: the light's setting
  bool animate = false;            // --animate: rebuild an animated built-in scene per frame
  double fps = 24.0;               // --fps: frame K is at time K / fps
  // Value overrides, set only when given on the command line.
  std::optional<float> poisson_spread, bias_constant, bias_slope, bias_slope_max, offset_factor, offset_units,
      normal_offset;
  // Technique parameters by key (vocabulary.h), set only when given.
  std::map<std::string, shading::tech::ParamValue> params;
};

// Every technique parameter once (the filter parameters and each built technique's own), in table order.
std::vector<const shading::tech::ParamSpec*> all_params() {
  std::vector<const shading::tech::ParamSpec*> out;
  auto add = [&](std::span<const shading::tech::ParamSpec> list) {
    for (const auto& p : list) {
      bool seen = false;
      for (const auto* q : out) seen |= q->key == p.key;
      if (!seen) out.push_back(&p);
    }
  };
  add(shading::tech::kFilterParams);
  for (const shading::tech::TechniqueInfo& t : shading::tech::kTechniques)
    if (t.built) add(t.params);
  return out;
}

// The command-line option of a library field named at the start of a FrameError, for messages.
std::string option_for_field(const std::string& field) {
  static const std::map<std::string, std::string> kFields = {
      {"size", "--size"},
      {"camera", "--camera"},
      {"technique", "--technique"},
      {"map_size", "--shadow-size"},
      {"poisson_taps", "--poisson-taps"},
      {"poisson_spread", "--poisson-spread"},
      {"bias.constant", "--bias-constant"},
      {"bias.slope", "--bias-slope"},
      {"bias.slope_max", "--bias-slope-max"},
      {"bias.offset_factor", "--offset-factor"},
      {"bias.offset_units", "--offset-units"},
      {"bias.normal_offset", "--normal-offset"},
  };
  if (const auto it = kFields.find(field); it != kFields.end()) return it->second;
  if (field.rfind("params.", 0) == 0)
    for (const auto* p : all_params())
      if (field == "params." + std::string(p->key)) return std::string(p->option);
  return field;
}

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

// --aov's comma-separated channel names (every channel when only --aov-out is given); empty without either.
std::vector<frame::AovChannel> parse_aov_list(const std::string& list, const std::string& out) {
  if (list.empty() && out.empty()) return {};
  if (out.empty()) throw CliError("--aov", "needs --aov-out FILE.exr to write the channels to");
  if (lower_extension(out) != ".exr") throw CliError("--aov-out", "expected an .exr file name");
  check_output_dir(out, "--aov-out");
  std::vector<frame::AovChannel> channels;
  if (list.empty()) {
    for (size_t i = 0; i < std::size(frame::kAovNames); ++i) channels.push_back(frame::AovChannel(i));
    return channels;
  }
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    const auto c = frame::parse_aov_channel(name);
    if (!c) throw CliError("--aov", "unknown channel '" + name + "' (known: position, normal, visibility, depth)");
    if (std::find(channels.begin(), channels.end(), *c) == channels.end()) channels.push_back(*c);
    start = end + 1;
  }
  return channels;
}

int run_render(const RenderArgs& a) {
  const Size2 size = parse_size(a.size, "--size");
  check_name(a.technique, "--technique", "technique", scenes::parse_technique(a.technique).has_value(),
             scenes::technique_names());
  check_name(a.filter, "--filter", "filter", scenes::parse_filter(a.filter).has_value(), scenes::filter_names());
  check_name(a.bias, "--bias", "bias mode", scenes::parse_bias_mode(a.bias).has_value(), scenes::bias_mode_names());
  check_name(a.depth_format, "--depth-format", "depth format", scenes::parse_depth_format(a.depth_format).has_value(),
             scenes::depth_format_names());
  if (!a.technique.empty() && !shading::tech::info(*scenes::parse_technique(a.technique)).built)
    throw CliError("--technique", "technique " + a.technique + " is not built yet");
  if (a.poisson_taps != 0 && a.poisson_taps != 4 && a.poisson_taps != 16)
    throw CliError("--poisson-taps", std::to_string(a.poisson_taps) + " is not 4 or 16");
  const std::optional<int> shadow_size =
      a.shadow_size_option->count() ? std::optional<int>(check_side(a.shadow_size, "--shadow-size")) : std::nullopt;
  check_threads(a.threads);
  if (a.frames < 1) throw CliError("--frames", "expected 1 or more frames");
  for (const shading::tech::ParamSpec* p : all_params())
    if (const auto it = a.params.find(std::string(p->key)); it != a.params.end())
      if (auto why = shading::tech::value_problem(*p, it->second)) throw CliError(std::string(p->option), *why);
  if (a.animate) {
    if (!std::isfinite(a.fps) || !(a.fps > 0.0)) throw CliError("--fps", "expected a frame rate above 0");
    bool animated = false;
    std::error_code ec;
    if (!std::filesystem::exists(a.scene, ec))
      for (const scenes::BuiltinInfo& b : scenes::list_builtin_scenes()) animated |= b.name == a.scene && b.animated;
    if (!animated) throw CliError("--animate", "'" + a.scene + "' is not an animated built-in scene (animated: projective)");
  }
  if (lower_extension(a.out) != ".png") throw CliError("--out", "expected a .png file name");
  check_output_dir(a.out, "--out");
  if (!a.aliasing.empty()) {
    if (lower_extension(a.aliasing) != ".png") throw CliError("--aliasing", "expected a .png file name");
    check_output_dir(a.aliasing, "--aliasing");
  }
  const std::vector<frame::AovChannel> aovs = parse_aov_list(a.aov, a.aov_out);
  if (!a.maps.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(a.maps, ec) && !std::filesystem::is_directory(a.maps, ec))
      throw CliError("--maps", a.maps + " exists and is not a directory");
  }

  scenes::Scene scene = load_scene_or_builtin(a.scene);
  frame::FrameConfig config;
  config.width = size.width;
  config.height = size.height;
  if (!a.technique.empty()) config.technique = scenes::parse_technique(a.technique);
  if (!a.filter.empty()) config.filter = scenes::parse_filter(a.filter);
  if (!a.bias.empty()) config.bias = scenes::parse_bias_mode(a.bias);
  if (!a.depth_format.empty()) config.depth_format = scenes::parse_depth_format(a.depth_format);
  config.map_size = shadow_size;
  config.cull_front = a.cull_front;
  if (a.poisson_taps != 0) config.poisson_taps = a.poisson_taps;
  config.poisson_spread = a.poisson_spread;
  config.bias_constant = a.bias_constant;
  config.bias_slope = a.bias_slope;
  config.bias_slope_max = a.bias_slope_max;
  config.offset_factor = a.offset_factor;
  config.offset_units = a.offset_units;
  config.normal_offset = a.normal_offset;
  config.params = a.params;
  config.export_maps = !a.maps.empty();  // projective maps become EXR records only when written
  config.aliasing = !a.aliasing.empty();
  config.surface_record = !aovs.empty();

  raster::Renderer renderer(a.threads);
  Progress progress;
  std::optional<frame::Frame> result;  // Frame has no empty state: the last frame rendered
  frame::FrameCache cache;             // projective maps live across frames: only changed casters are rebuilt
  for (int i = 0; i < a.frames; ++i) {
    if (a.animate && i > 0) scene = scenes::builtin_scene(a.scene, {double(i) / a.fps});
    if (a.frames > 1) progress.update("frame " + std::to_string(i + 1) + "/" + std::to_string(a.frames));
    const Stopwatch watch;
    try {
      result.emplace(frame::render_frame(scene, config, renderer, &cache));
    } catch (const frame::FrameError& e) {
      const std::string what = e.what();
      const size_t colon = what.find(": ");
      if (colon == std::string::npos) throw;
      throw CliError(option_for_field(what.substr(0, colon)), what.substr(colon + 2));
    }
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

  // Every output is staged, then committed together: a failure on any of them leaves none of the new files
  // (and no maps directory this run created).
  std::filesystem::path created_dir;
  try {
    scenes::io::WriteBatch batch;  // inside the try: its temporaries are gone before the handler runs
    if (!a.maps.empty()) {
      std::error_code ec;
      if (!std::filesystem::exists(a.maps, ec)) {
        std::filesystem::create_directories(a.maps, ec);
        if (ec) throw CliError("--maps", "cannot create directory " + a.maps + " (" + ec.message() + ")");
        created_dir = a.maps;
      }
      for (const frame::NamedMap& m : frame::export_maps(*result))
        scenes::io::write_exr_map(batch, std::filesystem::path(a.maps) / (m.name + ".exr"), m.map);
    }
    std::vector<std::pair<std::filesystem::path, raster::ColorTarget>> heat_maps;
    if (!a.aliasing.empty()) {
      size_t measured = 0;
      for (const frame::AliasingImage& img : result->aliasing) measured += img.measured > 0;
      if (measured == 0)
        throw CliError("--aliasing", "no light of this frame has a measured pixel (measured: shadowmap, cascades, "
                                     "lispsm, frustum-faces, esm, vsm, evsm2, evsm4, pcss, on pixels facing the "
                                     "light)");
      const std::filesystem::path base(a.aliasing);
      for (size_t i = 0; i < result->aliasing.size(); ++i) {
        const frame::AliasingImage& img = result->aliasing[i];
        if (img.measured == 0) continue;
        std::printf("aliasing %s (%s): max %.3g, p95 %.3g, mean %.3g pixels per texel over %zu lit-facing pixels; "
                    "storage factor %.3g\n",
                    result->lights[i].name.c_str(), std::string(shading::tech::to_string(result->lights[i].technique)).c_str(),
                    double(img.max), double(img.p95), double(img.mean), img.measured, double(img.storage_factor()));
        std::filesystem::path file = base;
        if (measured > 1) file.replace_filename(base.stem().string() + "-" + result->lights[i].name + ".png");
        heat_maps.emplace_back(file, frame::aliasing_heat_map(img));
      }
    }
    for (const auto& [file, heat] : heat_maps) scenes::io::write_png(batch, file, heat);
    if (!aovs.empty()) scenes::io::write_exr_image(batch, a.aov_out, frame::aov_image(*result->surface, aovs));
    scenes::io::write_png(batch, a.out, result->color);
    batch.commit();
  } catch (...) {
    std::error_code ec;
    if (!created_dir.empty()) std::filesystem::remove(created_dir, ec);  // only if it is still empty
    throw;
  }
  return 0;
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
  app->add_option("--aliasing", args->aliasing,
                  "Also measure each light's aliasing (pixels per shadow-map texel) and write its heat map here (.png)");
  app->add_flag_callback("--cull-front", [args] { args->cull_front = true; }, "Render only back faces into the maps");
  app->add_flag_callback("--no-cull-front", [args] { args->cull_front = false; }, "Render front faces into the maps");
  app->add_option("--poisson-taps", args->poisson_taps, "Poisson filters: 4 or 16 taps");
  RenderArgs& r = *args;
  add_value(app, "--poisson-spread", r.poisson_spread, "Poisson disc radius in map texture coordinates (1/700)");
  add_value(app, "--bias-constant", r.bias_constant, "constant bias: window depth subtracted (0.005)");
  add_value(app, "--bias-slope", r.bias_slope, "slope bias: scale of tan(acos(N.L)) (0.005)");
  add_value(app, "--bias-slope-max", r.bias_slope_max, "slope bias: upper clamp (0.01)");
  add_value(app, "--offset-factor", r.offset_factor, "offset bias: glPolygonOffset factor (1.1)");
  add_value(app, "--offset-units", r.offset_units, "offset bias: glPolygonOffset units (4)");
  add_value(app, "--normal-offset", r.normal_offset, "normal bias: receiver moved along its normal, metres (0.02)");
  app->add_option("--maps", args->maps, "Also write every shadow map as DIR/<map name>.exr");
  app->add_option("--aov", args->aov,
                  "Per-pixel channels to write with --aov-out: position,normal,visibility,depth (default: all)");
  app->add_option("--aov-out", args->aov_out, "Write the per-pixel channels as one multi-channel EXR (aligned with --out)");
  app->add_option("--depth-format", args->depth_format, "Depth format of every light's maps (see list)");
  // The technique parameters (vocabulary.h): one option each, flags with a --no- form.
  for (const shading::tech::ParamSpec* p : all_params()) {
    const std::string key(p->key), option(p->option), help = std::string(p->help) + " (default " +
                                                             std::string(p->fallback) + ")";
    switch (p->kind) {
      case shading::tech::ParamKind::flag:
        app->add_flag_callback(option, [args, key] { args->params[key] = true; }, help);
        app->add_flag_callback("--no-" + option.substr(2), [args, key] { args->params[key] = false; }, "");
        break;
      case shading::tech::ParamKind::number:
      case shading::tech::ParamKind::integer:
        app->add_option_function<double>(option, [args, key](const double& v) { args->params[key] = v; }, help);
        break;
      case shading::tech::ParamKind::choice:
      case shading::tech::ParamKind::text:
        app->add_option_function<std::string>(option, [args, key](const std::string& v) { args->params[key] = v; },
                                              help);
        break;
    }
  }
  app->add_flag("--animate", args->animate, "Animated built-in scenes (projective): frame K at time K / fps");
  app->add_option("--fps", args->fps, "Frame rate of --animate (default 24)");
  return {app, [args] { return run_render(*args); }};
}

}  // namespace cli
