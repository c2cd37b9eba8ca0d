// `shadowlab render SCENE...`: whole frames through the scenes/frame library, written as PNGs, with every shadow
// map as EXR on request, per-frame statistics with --stats, and --json for scripts (docs/cli/render.schema.json).
// Several scenes, or a batch file of render command lines, run in one process (start-up paid once); --shard I/N
// takes every N-th job and `render-merge` joins the shards' JSON. File names take `{scene}` (the scene's name)
// and a printf frame field (`frame_%04d.png`) for image sequences. This file only turns arguments into
// frame::FrameConfig: the technique parameters' options come from the vocabulary's ParamSpec lists.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/camera_choice.h"
#include "cli/light_choice.h"
#include "cli/look_options.h"
#include "cli/eval_report.h"
#include "cli/frame_record.h"
#include "cli/json_output.h"
#include "cli/render_line.h"
#include "cli/render_names.h"
#include "raster/renderer.h"
#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/exr_image.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/io_error.h"
#include "scenes/io/png_frame.h"
#include "scenes/shadow_settings.h"
#include "scenes/stage.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct RenderArgs {
  std::vector<std::string> scenes;
  std::string scene;  // the one scene of a job
  std::string technique, filter, bias, depth_format, size = "1280x720", maps, out = "frame.png", aliasing;
  std::string aov, aov_out;  // --aov position,normal,visibility,depth  --aov-out FILE.exr
  std::optional<long long> shadow_size;  // given or not (a plain value: jobs outlive the parser that filled them)
  std::optional<int> threads;  // --threads, left out for all cores
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
  bool ground = true;         // --ground / --no-ground: a plane under a bare glTF model (scenes/stage.h)
  std::string sun, up = "y";  // --sun AZ,EL for a bare model; --up y|z: the model's up axis
  std::string camera;         // --camera NAME|INDEX|orbit:AZ,EL[,DIST]
  std::string light;          // --light NAME|INDEX: that light alone
  LookArgs look;              // --exposure, --tonemap, --background
  bool json = false;          // --json: one document on stdout instead of text
  std::string batch, shard;   // --batch FILE, --shard I/N (top level only)
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

void add_render_options(CLI::App& command, const std::shared_ptr<RenderArgs>& args);

// Every check of a job's arguments that needs no rendering, so a bad job (or batch line) fails before any work.
void check_job(const RenderArgs& a) {
  parse_size(a.size, "--size");
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
  // The widest bounds any technique takes; each technique's own (16 and up for most, 1 for projective, less than
  // 16384 where maps share a target) are checked per light (vocabulary.h's map_size_problem).
  if (a.shadow_size && (*a.shadow_size < 1 || *a.shadow_size > 16384))
    throw CliError("--shadow-size", std::to_string(*a.shadow_size) +
                                        " is outside 1..16384 (16..16384 for every technique but projective)");
  check_threads(a.threads);
  if (a.frames < 1 || a.frames > 1000000) throw CliError("--frames", "expected 1 to 1000000 frames");
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
  if (a.up != "y" && a.up != "z") throw CliError("--up", "expected y or z, got '" + a.up + "'");
  if (!a.sun.empty()) {
    const auto [az, el] = parse_float_pair(a.sun, "--sun", "AZ,EL");
    if (!(el > 0.0f && el <= 90.0f)) throw CliError("--sun", "expected AZ,EL with an elevation above 0 and at most 90 degrees");
    (void)az;
  }
  if (a.camera.rfind("orbit:", 0) == 0) parse_orbit(a.camera);
  // Each output: its kind, its folder, and its frame field (the folder of a pattern is checked as it would be
  // for frame 1).
  const std::string stem = scene_stem(a.scene);
  if (a.out.empty()) throw CliError("--out", "is empty: give a .png file name");
  auto check_file = [&](const std::string& pattern, const char* option, const char* ext) {
    if (pattern.empty()) return;
    has_frame_field(pattern, option);
    const std::string first = expand_name(pattern, stem, 1);
    if (lower_extension(first) != ext) throw CliError(option, std::string("expected a ") + ext + " file name");
    check_output_dir(first, option);
  };
  check_file(a.out, "--out", ".png");
  check_file(a.aliasing, "--aliasing", ".png");
  parse_aov_list(a.aov, a.aov_out.empty() ? "" : expand_name(a.aov_out, stem, 1));
  if (!a.aov_out.empty()) has_frame_field(a.aov_out, "--aov-out");
  if (!a.maps.empty()) {
    has_frame_field(a.maps, "--maps");
    const std::string first = expand_name(a.maps, stem, 1);
    std::error_code ec;
    if (std::filesystem::exists(first, ec) && !std::filesystem::is_directory(first, ec))
      throw CliError("--maps", first + " exists and is not a directory");
    check_output_dir(first, "--maps");  // the folder is made, as the files are, but not the path to it
  }
  // Last: an option missing its value takes the next word (`--size --out f.png` makes f.png a scene), and the
  // option's own error says more than "no such file".
  check_scene_exists(a.scene);
}

// Stages frame `number`'s outputs in `batch`: maps, aliasing heat maps, AOVs and the PNG. The run commits the
// batch when every job has succeeded, so a failure anywhere (a later frame, a later scene or batch line) leaves
// none of the run's new files, nor a maps folder it made. Returns the files.
nlohmann::json write_outputs(const RenderArgs& a, const frame::Frame& result,
                             const std::vector<frame::AovChannel>& aovs, int number, bool text,
                             scenes::io::WriteBatch& batch) {
  const std::string stem = scene_stem(a.scene);
  nlohmann::json files = nlohmann::json::array();
  if (!a.maps.empty()) {
    const std::filesystem::path dir = expand_name(a.maps, stem, number);
    try {
      batch.create_directories(dir);
    } catch (const scenes::io::IoError& e) {
      throw CliError("--maps", e.reason());  // "cannot create the folder F (why)"
    }
    for (const frame::NamedMap& m : frame::export_maps(result)) {
      const std::filesystem::path file = dir / (m.name + ".exr");
      scenes::io::write_exr_map(batch, file, m.map);
      files.push_back(file.string());
    }
  }
  if (!a.aliasing.empty()) {
    size_t measured = 0;
    for (const frame::AliasingImage& img : result.aliasing) measured += img.measured > 0;
    if (measured == 0)
      throw CliError("--aliasing", "no light of this frame has a measured pixel (measured: shadowmap, cascades, "
                                   "lispsm, frustum-faces, esm, vsm, evsm2, evsm4, pcss, on pixels facing the "
                                   "light)");
    const std::filesystem::path base(expand_name(a.aliasing, stem, number));
    for (size_t i = 0; i < result.aliasing.size(); ++i) {
      const frame::AliasingImage& img = result.aliasing[i];
      if (img.measured == 0) continue;
      if (text)
        std::printf("aliasing %s (%s): max %.3g, p95 %.3g, mean %.3g pixels per texel over %zu lit-facing pixels; "
                    "storage factor %.3g\n",
                    result.lights[i].name.c_str(), std::string(shading::tech::to_string(result.lights[i].technique)).c_str(),
                    double(img.max), double(img.p95), double(img.mean), img.measured, double(img.storage_factor()));
      std::filesystem::path file = base;
      if (measured > 1) file.replace_filename(base.stem().string() + "-" + result.lights[i].name + ".png");
      scenes::io::write_png(batch, file, frame::aliasing_heat_map(img));
      files.push_back(file.string());
    }
  }
  if (!aovs.empty()) {
    const std::string file = expand_name(a.aov_out, stem, number);
    scenes::io::write_exr_image(batch, file, frame::aov_image(*result.surface, aovs));
    files.push_back(file);
  }
  const std::string out = expand_name(a.out, stem, number);
  scenes::io::write_png(batch, out, result.color);
  files.push_back(out);
  return files;
}

// One job: one scene, its frames, its outputs (staged in `outputs`). Text lines (--stats, aliasing) unless `text` is false.
nlohmann::json render_job(const RenderArgs& a, bool text, Progress& progress, const std::string& label,
                          scenes::io::WriteBatch& outputs) {
  const Size2 size = parse_size(a.size, "--size");
  const std::string stem = scene_stem(a.scene);
  const bool sequence = has_frame_field(a.out, "--out");
  const std::vector<frame::AovChannel> aovs = parse_aov_list(a.aov, a.aov_out.empty() ? "" : expand_name(a.aov_out, stem, 1));
  const LookOverrides look = parse_look(a.look);

  scenes::StageOptions stage;
  stage.ground = a.ground;
  if (!a.sun.empty()) {
    const auto [az, el] = parse_float_pair(a.sun, "--sun", "AZ,EL");
    stage.sun = glm::vec2(az, el);
  }
  stage.z_up = a.up == "z";
  stage.camera_chosen = a.camera.rfind("orbit:", 0) == 0;
  std::vector<std::string> notes;
  scenes::Scene scene = load_scene_or_builtin(a.scene, &stage, &notes);
  // Loaded once for every frame; a missing texture fails here, before anything is rendered or written.
  const scenes::io::SceneTextures textures = scenes::io::load_scene_textures(scene);
  frame::FrameConfig config;
  config.camera = choose_camera(scene, a.camera);
  const std::optional<size_t> chosen_light = choose_light(scene, a.light);
  print_notes(notes);
  config.width = size.width;
  config.height = size.height;
  if (!a.technique.empty()) config.technique = scenes::parse_technique(a.technique);
  if (!a.filter.empty()) config.filter = scenes::parse_filter(a.filter);
  if (!a.bias.empty()) config.bias = scenes::parse_bias_mode(a.bias);
  if (!a.depth_format.empty()) config.depth_format = scenes::parse_depth_format(a.depth_format);
  if (a.shadow_size) config.map_size = int(*a.shadow_size);
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
  config.exposure = look.exposure;
  config.tone_map = look.tone_map;
  config.background = look.background;

  raster::Renderer renderer(check_threads(a.threads));
  std::optional<frame::Frame> result;  // Frame has no empty state: the last frame rendered
  frame::FrameCache cache;             // projective maps live across frames: only changed casters are rebuilt
  nlohmann::json frames = nlohmann::json::array();
  for (int i = 0; i < a.frames; ++i) {
    if (a.animate && i > 0) scene = scenes::builtin_scene(a.scene, {double(i) / a.fps});
    progress.update(label + (a.frames > 1 ? "frame " + std::to_string(i + 1) + "/" + std::to_string(a.frames) : "rendering"));
    const Stopwatch watch;
    if (result) {  // its outputs are written: its targets serve the next frame
      frame::recycle(std::move(*result), cache);
      result.reset();
    }
    try {
      result.emplace(frame::render_frame(scene, config, renderer, &cache, &textures));
    } catch (const frame::FrameError& e) {
      const std::string what = e.what();
      const size_t colon = what.find(": ");
      if (colon == std::string::npos) throw;
      // A field of the scene file (not one the command line set) is named with the file, as loading errors are.
      std::string where = option_for_field(light_field(what.substr(0, colon), chosen_light));
      std::error_code ec;
      if (where.rfind("--", 0) != 0 && std::filesystem::is_regular_file(a.scene, ec)) where = a.scene + ": " + where;
      throw CliError(where, what.substr(colon + 2));
    }
    const double total = watch.ms();
    if (text && a.stats) {
      const frame::FrameStats& s = result->stats;
      std::printf(
          "frame %d: total %.3f ms, shadow %.3f ms, camera %.3f ms, maps %zu, triangles %llu, setups %llu, "
          "clipped %llu, culled %llu, rejected %llu\n",
          i + 1, total, s.shadow_ms, s.camera_ms, s.maps_rendered, (unsigned long long)s.draws.triangles,
          (unsigned long long)s.draws.setups, (unsigned long long)s.draws.clipped,
          (unsigned long long)s.draws.culled, (unsigned long long)s.draws.rejected);
      if (s.projective.active)
        std::printf("frame %d: maps rebuilt %zu, reused %zu, skipped %zu\n", i + 1, s.projective.maps_rebuilt,
                    s.projective.maps_reused, s.projective.maps_skipped);
      for (const frame::LightResult& l : result->lights) {
        if (!l.shadow) continue;
        std::string line;
        for (const shading::tech::TechniqueStat& t : l.shadow->stats()) {
          char value[64];
          std::snprintf(value, sizeof value, "%s %.6g", t.name.c_str(), t.value);
          line += (line.empty() ? "" : ", ") + std::string(value);
        }
        if (!line.empty()) std::printf("frame %d: %s: %s\n", i + 1, l.name.c_str(), line.c_str());
      }
    }
    frames.push_back(frame_json(i + 1, total, *result, config));
    // An image sequence writes every frame; otherwise the last frame is the one written.
    if (sequence || i + 1 == a.frames) frames.back()["outputs"] = write_outputs(a, *result, aovs, i + 1, text, outputs);
  }
  return {{"scene", a.scene}, {"name", stem}, {"frames", frames}};
}

// One job's arguments from `parse` (which runs a parser holding the render options over a command line): one
// scene, and none of the top-level-only options. Errors are CliErrors on `where`.
RenderArgs parse_job(const std::string& where, const std::function<void(CLI::App&)>& parse) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App parser{"render job"};
  add_render_options(parser, args);
  try {
    parse(parser);
  } catch (const CLI::ParseError& e) {
    throw CliError(where, e.what());
  }
  if (args->scenes.size() != 1) throw CliError(where, "a job renders exactly one scene");
  if (!args->batch.empty() || !args->shard.empty() || args->json)
    throw CliError(where, "--batch, --shard and --json belong on the command line, not in a job");
  args->scene = args->scenes[0];
  return *args;
}

// A batch file: one render command line per line (without `shadowlab render`), '#' comments and blank lines
// skipped; each parsed by the same options as the command line.
std::vector<std::pair<std::string, RenderArgs>> read_batch(const std::string& file) {
  std::ifstream in(file);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec) || !in) throw CliError(file, "cannot be read (no such file?)");
  std::vector<std::pair<std::string, RenderArgs>> jobs;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (jobs.size() >= 100000) throw CliError(file, "more than 100000 jobs");
    const std::string where = file + ":" + std::to_string(number);
    if (line.find('\0') != std::string::npos) throw CliError(where, "holds a NUL byte (not a text line)");
    char open = 0;  // the quote a word is inside, as CLI11's split reads them
    for (size_t i = 0; i < line.size(); ++i) {
      if (open == 0 && (line[i] == '\'' || line[i] == '"')) open = line[i];
      else if (line[i] == open) open = 0;
    }
    if (open != 0) throw CliError(where, std::string("a quote (") + open + ") is not closed");
    jobs.emplace_back(where, parse_job(where, [&](CLI::App& parser) { parser.parse(line, false); }));
  }
  if (jobs.empty()) throw CliError(file, "holds no render line");
  return jobs;
}

// No two jobs of a run write the same file or maps folder (the later would silently replace the earlier's):
// compared by the names of their first frames, where any two jobs' names meet if they meet at all but for
// sequences whose patterns differ.
void check_distinct_outputs(const std::vector<std::pair<std::string, RenderArgs>>& jobs) {
  std::map<std::string, std::string> owner;  // lexically normal path -> the job that writes it
  for (const auto& [where, a] : jobs) {
    const std::string stem = scene_stem(a.scene);
    const std::pair<const std::string*, const char*> outputs[] = {
        {&a.out, "--out"}, {&a.maps, "--maps"}, {&a.aliasing, "--aliasing"}, {&a.aov_out, "--aov-out"}};
    for (const auto& [pattern, option] : outputs) {
      if (pattern->empty()) continue;
      const std::string name = std::filesystem::path(expand_name(*pattern, stem, 1)).lexically_normal().string();
      const std::string job = where.empty() ? "scene " + a.scene : where;
      const auto [it, fresh] = owner.emplace(name, job);
      if (!fresh)
        throw CliError(where.empty() ? std::string(option) : where + ": " + option,
                       name + " is written by " + it->second + " as well");
    }
  }
}

int run_render(const RenderArgs& top) {
  std::vector<std::pair<std::string, RenderArgs>> jobs;  // where (batch file:line, or "") and arguments
  if (!top.batch.empty()) {
    if (!top.scenes.empty()) throw CliError("--batch", "takes its scenes from the file: give no scene arguments");
    jobs = read_batch(top.batch);
  } else {
    if (top.scenes.empty()) throw CliError("render", "no scene given (a file, a built-in name, or --batch FILE)");
    for (const std::string& scene : top.scenes) {
      RenderArgs a = top;
      a.scene = scene;
      jobs.emplace_back("", a);
    }
  }
  const Shard shard = parse_shard(top.shard, "--shard");
  // Every job is checked before the first renders.
  for (const auto& [where, a] : jobs) {
    try {
      check_job(a);
    } catch (const CliError& e) {
      if (where.empty()) throw;
      throw CliError(where, e.what());
    }
  }
  if (top.batch.empty()) {
    if (top.scenes.size() > 1) {
      auto needs_scene = [&](const std::string& pattern, const char* option) {
        if (!pattern.empty() && !has_scene_field(pattern))
          throw CliError(option, "several scenes would write to the same file: put {scene} in the name");
      };
      needs_scene(top.out, "--out");
      needs_scene(top.maps, "--maps");
      needs_scene(top.aliasing, "--aliasing");
      needs_scene(top.aov_out, "--aov-out");
    }
  }
  check_distinct_outputs(jobs);
  Progress progress;
  scenes::io::WriteBatch outputs;  // every job's files, renamed into place together once all have succeeded
  nlohmann::json done = nlohmann::json::array();
  const Stopwatch watch;
  size_t frames = 0;
  for (size_t k = 0; k < jobs.size(); ++k) {
    if (k % shard.count != shard.index) continue;
    const auto& [where, a] = jobs[k];
    const std::string label = jobs.size() > 1 ? "job " + std::to_string(k + 1) + "/" + std::to_string(jobs.size()) + " " + a.scene + ": " : "";
    nlohmann::json j;
    try {
      j = render_job(a, !top.json, progress, label, outputs);
    } catch (const CliError& e) {
      if (where.empty()) throw;
      throw CliError(where, e.what());
    }
    j["index"] = k;
    j["where"] = where.empty() ? nlohmann::json(nullptr) : nlohmann::json(where);
    frames += j["frames"].size();
    done.push_back(std::move(j));
  }
  outputs.commit();
  if (top.json) {
    print_json({{"command", "render"},
                {"batch", top.batch.empty() ? nlohmann::json(nullptr) : nlohmann::json(top.batch)},
                {"jobs_total", jobs.size()},
                {"shard", {{"index", shard.index}, {"count", shard.count}}},
                {"jobs", done},
                {"summary", {{"jobs", done.size()}, {"frames", frames}, {"wall_ms", watch.ms()}}}});
  }
  return 0;
}


void add_render_options(CLI::App& command, const std::shared_ptr<RenderArgs>& args) {
  CLI::App* app = &command;
  app->add_option("scenes", args->scenes,
                  "Scenes: JSON files, .gltf/.glb files or built-in names (see list); several run in one process");
  app->add_option("--technique", args->technique, "Shadow technique for every light (see list)");
  app->add_option("--filter", args->filter, "Shadow filter for every light (see list)");
  app->add_option("--bias", args->bias, "Bias mode for every light (see list)");
  app->add_option("--size", args->size, "Frame size WIDTHxHEIGHT (default 1280x720)");
  app->add_option_function<long long>(
      "--shadow-size", [args](const long long& v) { args->shadow_size = v; }, "Shadow map side in texels");
  add_threads_option(*app, args->threads);
  app->add_option("--frames", args->frames,
                  "Render N frames (timing, --animate); the last is written, or each with a frame field in --out");
  app->add_flag("--stats", args->stats, "Print per-frame timings and triangle counts");
  app->add_option("--out", args->out,
                  "Output PNG (default frame.png); {scene} is the scene's name, %04d the frame number (1, 2, ...)");
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
  app->add_flag_callback("--ground", [args] { args->ground = true; },
                         "A glTF model with no lights gets a ground plane and a sun (the default)");
  app->add_flag_callback("--no-ground", [args] { args->ground = false; }, "No ground plane under a bare glTF model");
  app->add_option("--sun", args->sun, "AZ,EL: the sun a glTF model with no lights gets (default: 105 degrees round from the camera, 50 up)");
  app->add_option("--up", args->up, "y|z: a glTF model's up axis (z: rotated to +Y; default y)");
  app->add_option("--camera", args->camera,
                  "NAME, INDEX or orbit:AZ,EL[,DIST]: the camera (orbit: around the casters, framed when DIST is left out)");
  app->add_option("--light", args->light,
                  "NAME or INDEX: render that light of the scene alone (a bare glTF model's staged sun is 'sun')");
  add_look_options(*app, args->look);
  app->add_flag("--json", args->json, "Print JSON (docs/cli/render.schema.json) instead of text");
  app->add_option("--batch", args->batch,
                  "Run every line of FILE as a render command line (no scene arguments), in one process");
  app->add_option("--shard", args->shard, "I/N: run only the jobs K with K mod N = I; join with render-merge");
}

}  // namespace

namespace {
RenderArgs parse_line(const std::vector<std::string>& args, const std::string& where) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes a vector last argument first
  return parse_job(where, [&](CLI::App& parser) { parser.parse(reversed); });
}
}  // namespace

void check_render_line(const std::vector<std::string>& args, const std::string& where) {
  const RenderArgs a = parse_line(args, where);
  try {
    check_job(a);
  } catch (const CliError& e) {
    throw CliError(where, e.what());
  }
}

nlohmann::json render_line(const std::vector<std::string>& args, const std::string& where) {
  const RenderArgs a = parse_line(args, where);
  Progress quiet;  // (a terminal still sees progress)
  try {
    check_job(a);
    scenes::io::WriteBatch outputs;
    nlohmann::json j = render_job(a, false, quiet, where + ": ", outputs);
    outputs.commit();
    return j;
  } catch (const CliError& e) {
    throw CliError(where, e.what());
  }
}

Command add_render_command(CLI::App& parent) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* app = parent.add_subcommand(
      "render", "Render scenes: shadow maps, then the shaded camera view (several scenes or --batch in one process)");
  add_render_options(*app, args);
  return {app, [args] { return run_render(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
