// A render job's arguments, options and checks (see render_jobs.h).
#include "cli/render_jobs.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "cli/camera_choice.h"
#include "cli/cli_common.h"
#include "cli/render_names.h"
#include "scenes/builtin_scenes.h"
#include "scenes/shadow_settings.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

// An override's name is checked against the scene module's table before anything is loaded.
void check_name(const std::string& value, const std::string& option, const char* what, bool known,
                std::span<const scenes::NamedEntry> table) {
  if (!value.empty() && !known)
    throw CliError(option, std::string("unknown ") + what + " '" + value + "' (known: " + scenes::join_names(table) +
                               ")");
}

}  // namespace

// The command-line option of a library field named at the start of a FrameError, for messages.
std::string option_for_field(const std::string& field) {
  static const std::map<std::string, std::string> kFields = {
      {"size", "--size"},
      {"camera", "--camera"},
      {"technique", "--technique"},
      {"map_size", "--shadow-size"},
  };
  if (const auto it = kFields.find(field); it != kFields.end()) return it->second;
  if (auto option = shadow_option_for_field(field)) return *option;
  return field;
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

scenes::StageOptions::Up up_axis(const std::string& up) {
  using Up = scenes::StageOptions::Up;
  if (up == "y") return Up::y;
  if (up == "z") return Up::z;
  if (up == "-y") return Up::minus_y;
  if (up == "-z") return Up::minus_z;
  throw CliError("--up", "expected y, z, -y or -z, got '" + up + "'");
}

// Every check of a job's arguments that needs no rendering, so a bad job (or batch line) fails before any work.
void check_job(const RenderArgs& a) {
  parse_size(a.size, "--size");
  check_name(a.technique, "--technique", "technique", scenes::parse_technique(a.technique).has_value(),
             scenes::technique_names());
  check_name(a.filter, "--filter", "filter", scenes::parse_filter(a.filter).has_value(), scenes::filter_names());
  check_name(a.bias, "--bias", "bias mode", scenes::parse_bias_mode(a.bias).has_value(), scenes::bias_mode_names());
  if (!a.technique.empty() && !shading::tech::info(*scenes::parse_technique(a.technique)).built)
    throw CliError("--technique", "technique " + a.technique + " is not built yet");
  check_shadow_overrides(a.shadow);
  // The widest bounds any technique takes; each technique's own (16 and up for most, 1 for projective, less than
  // 16384 where maps share a target) are checked per light (vocabulary.h's map_size_problem).
  if (a.shadow_size && (*a.shadow_size < 1 || *a.shadow_size > 16384))
    throw CliError("--shadow-size", a.shadow_size_text +
                                        " is outside 1..16384 (16..16384 for every technique but projective)");
  check_threads(a.threads);
  if (a.frames < 1 || a.frames > 1000000) throw CliError("--frames", "expected 1 to 1000000 frames");
  if (a.fps && !a.animate) throw CliError("--fps", "sets the frame rate of --animate, which is not given");
  if (a.animate) {
    if (a.fps && (!std::isfinite(*a.fps) || !(*a.fps > 0.0))) throw CliError("--fps", "expected a frame rate above 0");
    bool animated = false;
    std::error_code ec;
    if (!std::filesystem::exists(a.scene, ec))
      for (const scenes::BuiltinInfo& b : scenes::list_builtin_scenes()) animated |= b.name == a.scene && b.animated;
    if (!animated) throw CliError("--animate", "'" + a.scene + "' is not an animated built-in scene (animated: projective)");
  }
  up_axis(a.up);
  if (!a.sun.empty()) {
    const auto [az, el] = parse_float_pair(a.sun, "--sun", "AZ,EL");
    if (!(el > 0.0f && el <= 90.0f)) throw CliError("--sun", "expected AZ,EL with an elevation above 0 and at most 90 degrees");
    (void)az;
  }
  // The staging options shape a bare glTF model only (scenes/stage.h): on a scene file or a built-in they would
  // do nothing.
  if (const std::string ext = lower_extension(a.scene); ext != ".gltf" && ext != ".glb") {
    const char* given = !a.sun.empty() ? "--sun" : a.up != "y" ? "--up" : !a.ground ? "--no-ground" : nullptr;
    if (given) throw CliError(given, "stages a .gltf/.glb model; " + a.scene + " is a scene of its own");
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

RenderArgs parse_line(const std::vector<std::string>& args, const std::string& where) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes a vector last argument first
  return parse_job(where, [&](CLI::App& parser) { parser.parse(reversed); });
}

void add_render_options(CLI::App& command, const std::shared_ptr<RenderArgs>& args) {
  CLI::App* app = &command;
  app->add_option("scenes", args->scenes,
                  "Scenes: JSON files, .gltf/.glb files or built-in names (see list); several run in one process");
  app->add_option("--technique", args->technique, "Shadow technique for every light (see list)");
  app->add_option("--filter", args->filter, "Shadow filter for every light (see list)");
  app->add_option("--bias", args->bias, "Bias mode for every light (see list)");
  app->add_option("--size", args->size, "Frame size WIDTHxHEIGHT (default 1280x720)");
  app->add_option_function<std::string>(
      "--shadow-size",
      [args](const std::string& text) {
        // Read here rather than by CLI11, whose integer conversion saturates: 99999999999999999999 would be
        // reported as 9223372036854775807. A number beyond long long is kept as out of bounds, with its text.
        long long v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (text.empty() || end != text.data() + text.size() ||
            (ec != std::errc() && ec != std::errc::result_out_of_range))
          throw CLI::ConversionError("--shadow-size", std::vector<std::string>{text});
        args->shadow_size = ec == std::errc() ? v : std::numeric_limits<long long>::max();
        args->shadow_size_text = text;
      },
      "Shadow map side in texels");
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
  app->add_option("--maps", args->maps, "Also write every shadow map as DIR/<map name>.exr");
  app->add_option("--aov", args->aov,
                  "Per-pixel channels to write with --aov-out: position,normal,visibility,depth (default: all)");
  app->add_option("--aov-out", args->aov_out, "Write the per-pixel channels as one multi-channel EXR (aligned with --out)");
  add_shadow_options(*app, args->shadow);
  app->add_flag("--animate", args->animate, "Animated built-in scenes (projective): frame K at time K / fps");
  app->add_option("--fps", args->fps, "Frame rate of --animate (default 24)");
  app->add_flag_callback("--ground", [args] { args->ground = true; },
                         "A glTF model with no lights gets a ground plane and a sun (the default)");
  app->add_flag_callback("--no-ground", [args] { args->ground = false; }, "No ground plane under a bare glTF model");
  app->add_option("--sun", args->sun, "AZ,EL: the sun a glTF model with no lights gets (default: 105 degrees round from the camera, 50 up)");
  app->add_option("--up", args->up,
                  "y|z|-y|-z: a glTF model's up axis, turned to +Y (default y; write --up=-y for the negative ones)");
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


SHADOWLAB_ISA_END
}  // namespace cli
