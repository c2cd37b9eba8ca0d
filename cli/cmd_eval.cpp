// `shadowlab eval SCENE`: every combination of --techniques x --filters x --biases x --sizes rendered on the same
// view and scored against the exact ray-cast shadow (scenes/reference/): per light, false-shadowed and false-lit
// percentages of the lit-facing pixels near a boundary and elsewhere, mean |S - V|, the map and camera pass
// times, the aliasing measure where the technique has one (frame/aliasing.h), and on request shimmer under a
// sub-pixel camera slide and a small light turn (shimmer.h). Writes DIR/eval.csv, DIR/eval.json, DIR/eval.html and per combination a contact sheet, the frame beside
// its error map (DIR/<combination>.png). Every option is checked and every combination rendered before the first
// file is written, so a failed run writes none.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/eval_report.h"
#include "cli/light_choice.h"
#include "cli/shadow_options.h"
#include "raster/renderer.h"
#include "scenes/frame/frame.h"
#include "scenes/frame/frame_lights.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "scenes/io/png_frame.h"
#include "scenes/reference/error_map.h"
#include "scenes/reference/frame_reference.h"
#include "scenes/reference/shimmer.h"
#include "scenes/shadow_settings.h"
#include "scenes/stage.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace tech = shading::tech;

struct EvalArgs {
  std::string scene, techniques, filters, biases, sizes, size = "1280x720", out = "eval";
  std::optional<int> threads;  // --threads, left out for all cores
  int near_radius = 2;
  std::optional<bool> cull_front;  // --cull-front / --no-cull-front for every combination
  std::string shard;               // --shard I/N: only combinations K with K mod N = I
  std::string light;               // --light NAME|INDEX: score that light alone
  float shimmer_pixels = 0.0f;     // --shimmer-pixels: camera slide for the shimmer columns (0: not measured)
  float shimmer_degrees = 0.0f;    // --shimmer-degrees: light turn for the shimmer columns (0: not measured)
  ShadowOverrides shadow;          // settings for the whole sweep: bias values, Poisson, technique parameters
};

// One point of the sweep; an unset field keeps each light's own setting.
struct Combination {
  std::optional<tech::Technique> technique;
  std::optional<tech::FilterKind> filter;
  std::optional<tech::BiasMode> bias;
  std::optional<int> map_size;
  std::string label() const {
    return (technique ? std::string(tech::info(*technique).name) : std::string("scene")) + "-" +
           (filter ? std::string(tech::to_string(*filter)) : "scene") + "-" +
           (bias ? std::string(tech::to_string(*bias)) : "scene") + "-" +
           (map_size ? std::to_string(*map_size) : "scene");
  }
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  if (text.back() == ',') out.emplace_back();
  return out;
}

// A list of names through a vocabulary parser; empty: one unset entry (the lights' own settings).
template <class T, class Parse>
std::vector<std::optional<T>> parse_names(const std::string& text, const std::string& option, const char* what,
                                          Parse parse, std::span<const scenes::NamedEntry> table) {
  std::vector<std::optional<T>> out;
  for (const std::string& name : split_list(text)) {
    const auto v = parse(name);
    if (!v) throw CliError(option, std::string("unknown ") + what + " '" + name + "' (known: " + scenes::join_names(table) + ")");
    out.push_back(T(*v));
  }
  if (out.empty()) out.push_back(std::nullopt);
  return out;
}

std::vector<std::optional<int>> parse_sizes(const std::string& text) {
  std::vector<std::optional<int>> out;
  for (const std::string& item : split_list(text)) {
    size_t used = 0;
    long long v = -1;
    try {
      v = std::stoll(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size()) throw CliError("--sizes", "'" + item + "' is not a whole number");
    if (v < 16 || v > 16384) throw CliError("--sizes", std::to_string(v) + " is outside 16..16384");
    out.push_back(int(v));
  }
  if (out.empty()) out.push_back(std::nullopt);
  return out;
}

// A FrameError named where its field came from: the sweep's option for a field the command line set, else the
// scene file's field (a --light choice's lights[0] renamed to the light's place in the file), as render names them.
CliError as_cli_error(const frame::FrameError& e, const std::string& scene, std::optional<size_t> chosen_light) {
  const std::string what = e.what();
  const size_t colon = what.find(": ");
  if (colon == std::string::npos) return CliError("eval", what);
  static const std::map<std::string, std::string> kOptions = {
      {"size", "--size"}, {"map_size", "--sizes"}, {"technique", "--techniques"}, {"filter", "--filters"},
      {"bias", "--biases"}};
  const std::string field = light_field(what.substr(0, colon), chosen_light);
  std::string where = field;
  if (const auto it = kOptions.find(field); it != kOptions.end()) where = it->second;
  else if (auto option = shadow_option_for_field(field)) where = *option;
  else if (std::error_code ec; std::filesystem::is_regular_file(scene, ec)) where = scene + ": " + field;
  return CliError(where, what.substr(colon + 2));
}

// The frame a combination renders: the sweep's base, the combination's point, the command line's settings.
frame::FrameConfig combo_config(const frame::FrameConfig& base, const Combination& c, const ShadowOverrides& shadow) {
  frame::FrameConfig config = base;
  apply_shadow_overrides(shadow, config);
  config.technique = c.technique, config.filter = c.filter, config.bias = c.bias, config.map_size = c.map_size;
  return config;
}

// What a light was rendered with in a combination, where the label says "scene" (the light's own): the
// technique, the filter and bias where the technique reads them (null otherwise), the map size (0 for none) and
// the depth format of the maps that hold depths (null for none, projective's caster masks and irregular).
nlohmann::json used_json(const frame::ResolvedLight& used) {
  const tech::ShadowConfig& c = used.config;
  const tech::TechniqueInfo& info = tech::info(c.technique);
  const bool depth_map = c.technique != tech::Technique::none && c.technique != tech::Technique::projective &&
                         c.technique != tech::Technique::irregular;  // a map of depths, compared with a bias
  return {{"used_technique", std::string(info.name)},
          {"used_filter", info.reads_filter ? nlohmann::json(std::string(tech::to_string(c.filter))) : nlohmann::json()},
          {"used_bias", depth_map ? nlohmann::json(std::string(tech::to_string(c.bias.mode))) : nlohmann::json()},
          {"used_map_size", c.technique == tech::Technique::none ? 0 : c.map_size},
          {"used_depth_format", depth_map ? nlohmann::json(std::string(tech::to_string(c.depth_format))) : nlohmann::json()}};
}

// One row: a combination's score for one light.
nlohmann::json row_json(const scenes::Scene& scene, const Combination& c, size_t light,
                        const reference::LightScore& s, const frame::FrameStats& stats, double score_ms) {
  auto pct = [&](size_t n) { return s.percent(n); };
  return {{"combination", c.label()},
          {"technique", c.technique ? std::string(tech::info(*c.technique).name) : std::string("scene")},
          {"filter", c.filter ? std::string(tech::to_string(*c.filter)) : "scene"},
          {"bias", c.bias ? std::string(tech::to_string(*c.bias)) : "scene"},
          {"map_size", c.map_size ? *c.map_size : 0},
          {"light", light},
          {"light_name", scene.lights[light].name},
          {"scored_pixels", s.scored},
          {"unreached_pixels", s.unreached},
          {"false_shadowed_pct", pct(s.false_shadowed())},
          {"false_shadowed_near_pct", pct(s.false_shadowed_near)},
          {"false_shadowed_elsewhere_pct", pct(s.false_shadowed_elsewhere)},
          {"false_lit_pct", pct(s.false_lit())},
          {"false_lit_near_pct", pct(s.false_lit_near)},
          {"false_lit_elsewhere_pct", pct(s.false_lit_elsewhere)},
          {"false_shadowed_pixels", s.false_shadowed()},
          {"false_lit_pixels", s.false_lit()},
          {"mean_abs_error", s.mean_abs_error},
          {"largest_false_lit_group", s.largest_false_lit_group},
          {"longest_false_lit_run", s.longest_false_lit_run},
          {"map_pass_ms", stats.shadow_ms},
          {"camera_pass_ms", stats.camera_ms},
          {"score_ms", score_ms}};
}

int run_eval(const EvalArgs& a) {
  const Size2 size = parse_size(a.size, "--size");
  const auto techniques = parse_names<tech::Technique>(a.techniques, "--techniques", "technique",
                                                       scenes::parse_technique, scenes::technique_names());
  for (const auto& t : techniques) {
    if (!t) continue;
    if (!tech::info(*t).built) throw CliError("--techniques", "technique " + std::string(tech::info(*t).name) + " is not built yet");
  }
  const auto filters = parse_names<tech::FilterKind>(a.filters, "--filters", "filter", scenes::parse_filter,
                                                     scenes::filter_names());
  const auto biases = parse_names<tech::BiasMode>(a.biases, "--biases", "bias mode", scenes::parse_bias_mode,
                                                  scenes::bias_mode_names());
  const auto sizes = parse_sizes(a.sizes);
  check_threads(a.threads);
  check_shadow_overrides(a.shadow);
  if (a.near_radius < 0 || a.near_radius > 64) throw CliError("--near-radius", "expected 0..64 pixels");
  if (!std::isfinite(a.shimmer_pixels) || std::fabs(a.shimmer_pixels) > 16.0f)
    throw CliError("--shimmer-pixels", "expected a slide of at most 16 pixels");
  if (!std::isfinite(a.shimmer_degrees) || std::fabs(a.shimmer_degrees) > 45.0f)
    throw CliError("--shimmer-degrees", "expected a turn of at most 45 degrees");
  std::error_code ec;
  if (std::filesystem::exists(a.out, ec) && !std::filesystem::is_directory(a.out, ec))
    throw CliError("--out", a.out + " exists and is not a directory");
  check_output_dir(a.out, "--out");  // the folder it goes in must exist; it is created itself

  const Shard shard = parse_shard(a.shard, "--shard");
  std::vector<Combination> combos;  // the whole sweep, in a fixed order; this run takes its shard
  for (const auto& t : techniques)
    for (const auto& f : filters)
      for (const auto& b : biases)
        for (const auto& s : sizes) combos.push_back({t, f, b, s});
  const size_t sweep_size = combos.size();
  nlohmann::json labels = nlohmann::json::array();  // the whole sweep's, so that eval-merge can tell sweeps apart
  for (const Combination& c : combos) labels.push_back(c.label());

  // A bare glTF model gets its sun, ground and camera, as in render; the projective combinations see the ground
  // as render stages it for them, casting nothing (scenes/stage.h).
  const scenes::StageOptions stage;
  std::vector<std::string> notes;
  scenes::Scene scene = load_scene_or_builtin(a.scene, &stage, &notes);
  const std::optional<size_t> chosen_light = choose_light(scene, a.light);
  // The same scene (its light chosen) with the staged ground receiving only, where a ground was staged.
  std::optional<scenes::Scene> receivers_scene;
  bool projective = false;
  for (const auto& t : techniques) projective |= t == tech::Technique::projective;
  if (projective && scene.staged_ground) scenes::ground_receives_only(receivers_scene.emplace(scene));
  const scenes::io::SceneTextures textures = scenes::io::load_scene_textures(scene);  // once for the sweep
  print_notes(notes);
  raster::Renderer renderer(check_threads(a.threads));
  frame::FrameConfig base;
  base.width = size.width, base.height = size.height;
  base.export_maps = false;
  base.cull_front = a.cull_front;
  reference::ScoreOptions options;
  options.near_radius = a.near_radius;

  // The --out folder, made now so that a run that cannot make it fails first; removed again (when empty) if the
  // run fails.
  scenes::io::WriteBatch out_folder;
  make_folder(out_folder, a.out, "--out");

  try {
    // Every combination's lights resolved (technique for the light type, map size, parameters) before anything
    // renders, so a sweep with a bad combination fails before the first. A technique parameter of the command
    // line goes to the combinations whose lights read it (--esm-c beside --techniques shadowmap,esm: the esm
    // ones); one that no combination reads would do nothing, and is refused with the first combination's reason.
    std::vector<std::map<std::string, tech::ParamValue>> combo_params(combos.size());
    std::map<std::string, std::string> unread;  // key -> why the first combination leaves it unread
    std::set<std::string> read;
    for (size_t k = 0; k < combos.size(); ++k) {
      frame::FrameConfig config = combo_config(base, combos[k], a.shadow);
      std::vector<frame::ResolvedLight> lights;
      for (size_t i = 0; i < scene.lights.size(); ++i) lights.push_back(frame::resolve_light(scene.lights[i], i, config));
      for (const auto& [key, value] : a.shadow.params) {
        if (auto why = frame::unread_override(lights, key, value)) unread.emplace(key, *why);
        else read.insert(key), combo_params[k].emplace(key, value);
      }
    }
    for (const auto& [key, why] : unread)
      if (!read.count(key)) {
        if (combos.size() == 1) throw frame::FrameError(why);
        const std::string field = "params." + key + ": ";  // why starts with it
        throw frame::FrameError(field + "no combination of the sweep reads it (the first: " + why.substr(field.size()) + ")");
      }

    Progress progress;
    progress.update("reference: casting rays");
    // The scenes a combination renders: its reference, and the moved views of the shimmer columns with theirs,
    // each cast once for the sweep.
    struct Moved {
      std::string column;
      scenes::Scene scene;
      std::optional<reference::FrameReference> ref;
    };
    struct Variant {
      const scenes::Scene* scene;
      reference::FrameReference ref;
      std::vector<Moved> motions;
    };
    auto variant = [&](const scenes::Scene& s) {
      Variant v{&s, reference::reference_for(s, base, renderer, -1.0f, &textures), {}};
      if (a.shimmer_pixels != 0.0f)
        v.motions.push_back({"shimmer_camera_pct", reference::moved(s, base.camera, base.height, {a.shimmer_pixels, 0.0f}), {}});
      if (a.shimmer_degrees != 0.0f)
        v.motions.push_back({"shimmer_light_pct", reference::moved(s, base.camera, base.height, {0.0f, a.shimmer_degrees}), {}});
      for (Moved& m : v.motions) m.ref.emplace(reference::reference_for(m.scene, base, renderer, -1.0f, &textures));
      return v;
    };
    const Variant main = variant(scene);
    const std::optional<Variant> receivers = receivers_scene ? std::optional<Variant>(variant(*receivers_scene)) : std::nullopt;
    const reference::FrameReference& ref = main.ref;
    const double rays_per_s = ref.exact.ms > 0 ? double(ref.exact.rays) / (ref.exact.ms / 1000.0) : 0.0;
    std::printf("reference: %zu triangles, BVH %.1f ms; %zu rays in %.1f ms (%.2f Mrays/s); epsilon %g\n",
                ref.triangles, ref.bvh_ms, ref.exact.rays, ref.exact.ms, rays_per_s / 1e6, double(ref.exact.epsilon));

    nlohmann::json rows = nlohmann::json::array();
    ContactSheets sheets;  // encoded as each combination ends: a sweep keeps PNG bytes, not whole frames
    std::set<std::string> warned;  // frame warnings said so far: each once per sweep
    for (size_t k = 0; k < combos.size(); ++k) {
      if (k % shard.count != shard.index) continue;
      const Combination& c = combos[k];
      progress.update("combination " + std::to_string(k + 1) + "/" + std::to_string(combos.size()) + ": " + c.label());
      frame::FrameConfig config = combo_config(base, c, a.shadow);
      config.params = combo_params[k];
      config.aliasing = true;  // measured where the technique has a measure (frame/aliasing.h)
      const Variant& v = receivers && c.technique == tech::Technique::projective ? *receivers : main;
      const reference::ScoredFrame sf = reference::score_config(*v.scene, config, renderer, v.ref, options, &textures);
      print_frame_warnings(a.scene, sf.frame.warnings, chosen_light, warned);
      std::vector<std::vector<reference::LightShimmer>> shimmers;
      for (const Moved& m : v.motions) {
        const reference::ScoredFrame moved = reference::score_config(m.scene, config, renderer, *m.ref, options, &textures);
        shimmers.push_back(reference::compare_frames(*sf.frame.surface, v.ref.exact, *moved.frame.surface, m.ref->exact,
                                                     options.shadow_below));
      }
      for (size_t l = 0; l < sf.score.lights.size(); ++l) {
        rows.push_back(row_json(scene, c, l, sf.score.lights[l], sf.frame.stats, sf.score_ms));
        rows.back()["index"] = k;
        const nlohmann::json used = used_json(frame::resolve_light(v.scene->lights[l], l, config));
        rows.back().update(used);
        rows.back()["shimmer_camera_pct"] = nullptr;
        rows.back()["shimmer_light_pct"] = nullptr;
        for (size_t m = 0; m < v.motions.size(); ++m) rows.back()[v.motions[m].column] = shimmers[m][l].percent();
        const frame::AliasingImage* al = l < sf.frame.aliasing.size() ? &sf.frame.aliasing[l] : nullptr;
        const bool measured = al && al->measured > 0;
        rows.back()["aliasing_max"] = measured ? nlohmann::json(al->max) : nlohmann::json(nullptr);
        rows.back()["aliasing_p95"] = measured ? nlohmann::json(al->p95) : nlohmann::json(nullptr);
        rows.back()["aliasing_mean"] = measured ? nlohmann::json(al->mean) : nlohmann::json(nullptr);
        const reference::LightScore& s = sf.score.lights[l];
        // The settings the label leaves to the scene, said after it: "scene-scene-scene-scene (shadowmap pcf slope 2048 d24)".
        std::string said = used.at("used_technique").get<std::string>();
        for (const char* k : {"used_filter", "used_bias"})
          if (!used.at(k).is_null()) said += " " + used.at(k).get<std::string>();
        if (used.at("used_map_size").get<int>() > 0) said += " " + std::to_string(used.at("used_map_size").get<int>());
        if (!used.at("used_depth_format").is_null()) said += " " + used.at("used_depth_format").get<std::string>();
        std::printf("%s (%s) light%zu: false-shadowed %.3f%% (near %.3f%%), false-lit %.3f%% (near %.3f%%), mean |S-V| %.4f\n",
                    c.label().c_str(), said.c_str(), l, s.percent(s.false_shadowed()), s.percent(s.false_shadowed_near),
                    s.percent(s.false_lit()), s.percent(s.false_lit_near), s.mean_abs_error);
      }
      // The sheet shows the first light's aliasing heat map where it was measured.
      std::optional<raster::ColorTarget> heat;
      if (!sf.frame.aliasing.empty() && sf.frame.aliasing[0].measured > 0)
        heat.emplace(frame::aliasing_heat_map(sf.frame.aliasing[0]));
      sheets[c.label()] = scenes::io::encode_png(
          reference::contact_sheet(sf.frame.color, sf.score.errors, heat ? &*heat : nullptr), false, c.label() + ".png");
    }

    const nlohmann::json report = {
        {"scene", scene.name.empty() ? a.scene : scene.name},
        {"frame", {{"width", size.width}, {"height", size.height}}},
        {"reference",
         {{"triangles", ref.triangles}, {"bvh_ms", ref.bvh_ms}, {"rays", ref.exact.rays}, {"rays_ms", ref.exact.ms},
          {"rays_per_second", rays_per_s}, {"epsilon", ref.exact.epsilon}}},
        {"scoring", {{"shadow_below", options.shadow_below}, {"near_radius_pixels", options.near_radius}}},
        {"sweep",
         {{"combinations", sweep_size},
          {"labels", labels},
          {"light", chosen_light ? nlohmann::json(*chosen_light) : nlohmann::json()},
          {"cull_front", a.cull_front ? nlohmann::json(*a.cull_front) : nlohmann::json()},
          {"settings", shadow_overrides_json(a.shadow)},
          {"shard", shard.index},
          {"shards", shard.count}}},
        {"shimmer", {{"camera_pixels", a.shimmer_pixels}, {"light_degrees", a.shimmer_degrees}}},
        {"results", rows}};
    const std::filesystem::path dir(a.out);
    write_eval_report(dir, report, sheets);
    out_folder.commit();
  } catch (const frame::FrameError& e) {
    throw as_cli_error(e, a.scene, chosen_light);
  }
  return 0;
}

}  // namespace

Command add_eval_command(CLI::App& parent) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* app = parent.add_subcommand(
      "eval", "Score shadow techniques against the exact ray-cast shadow over a sweep of settings");
  app->add_option("scene", args->scene, "Scene: a JSON file, a .gltf/.glb file, or a built-in name (see list)")
      ->required();
  app->add_option("--techniques", args->techniques, "Comma-separated techniques (default: each light's own)");
  app->add_option("--filters", args->filters, "Comma-separated filters (default: each light's own)");
  app->add_option("--biases", args->biases, "Comma-separated bias modes (default: each light's own)");
  app->add_option("--sizes", args->sizes, "Comma-separated shadow map sides, 16..16384 (default: each light's own)");
  app->add_option("--size", args->size, "Frame size WIDTHxHEIGHT (default 1280x720)");
  app->add_option("--light", args->light, "NAME or INDEX: score that light of the scene alone (default: every light)");
  add_threads_option(*app, args->threads);
  app->add_flag_callback("--cull-front", [args] { args->cull_front = true; }, "Render only back faces into the maps");
  app->add_flag_callback("--no-cull-front", [args] { args->cull_front = false; }, "Render front faces into the maps");
  app->add_option("--near-radius", args->near_radius, "Pixels from an exact shadow boundary counted as near it (default 2)");
  app->add_option("--shimmer-pixels", args->shimmer_pixels,
                  "Also measure shimmer: pixels flipping when the camera slides sideways by this many pixels");
  app->add_option("--shimmer-degrees", args->shimmer_degrees,
                  "Also measure shimmer: pixels flipping when every light turns by this many degrees");
  app->add_option("--shard", args->shard,
                  "I/N: run only the combinations K with K mod N = I (0 <= I < N); merge the shards with eval-merge");
  app->add_option("--out", args->out, "Output directory for eval.csv, eval.json and the error maps (default eval)");
  // The shadow settings render takes, the same for every combination (each light's own where not given).
  add_shadow_options(*app, args->shadow);
  return {app, [args] { return run_eval(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
