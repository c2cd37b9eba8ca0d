// `shadowlab render SCENE...`: whole frames through the scenes/frame library, written as PNGs, with every shadow
// map as EXR on request, per-frame statistics with --stats, and --json for scripts (docs/cli/render.schema.json).
// Several scenes, or a batch file of render command lines, run in one process (start-up paid once); --shard I/N
// takes every N-th job and `render-merge` joins the shards' JSON. File names take `{scene}` (the scene's name)
// and a printf frame field (`frame_%04d.png`) for image sequences. This file turns a job's arguments
// (render_jobs.h: the options, their checks, batch files) into frame::FrameConfig and stages its files.
#include <cstdio>
#include <filesystem>
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
#include "cli/render_jobs.h"
#include "cli/render_line.h"
#include "cli/render_names.h"
#include "raster/renderer.h"
#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/exr_image.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#include "scenes/shadow_settings.h"
#include "scenes/stage.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {
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
    make_folder(batch, dir, "--maps");
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
  stage.up = up_axis(a.up);
  stage.camera_chosen = a.camera.rfind("orbit:", 0) == 0;
  std::vector<std::string> notes;
  scenes::Scene scene = load_scene_or_builtin(a.scene, &stage, &notes);
  if (a.technique == "projective") scenes::ground_receives_only(scene);
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
  if (a.shadow_size) config.map_size = int(*a.shadow_size);
  config.cull_front = a.cull_front;
  apply_shadow_overrides(a.shadow, config);
  config.export_maps = !a.maps.empty();  // projective maps become EXR records only when written
  config.aliasing = !a.aliasing.empty();
  config.surface_record = !aovs.empty();
  config.exposure = look.exposure;
  config.tone_map = look.tone_map;
  config.background = look.background;

  raster::Renderer renderer(check_threads(a.threads));
  std::optional<frame::Frame> result;  // Frame has no empty state: the last frame rendered
  frame::FrameCache cache;             // projective maps live across frames: only changed casters are rebuilt
  std::set<std::string> warned;        // frame warnings said so far (each once per sequence)
  nlohmann::json frames = nlohmann::json::array();
  for (int i = 0; i < a.frames; ++i) {
    if (a.animate && i > 0) {
      scenes::Scene moved = scenes::builtin_scene(a.scene, {double(i) / a.fps.value_or(24.0)});
      // The command line's choices made again on the moved scene: an orbit camera where the first frame put it,
      // and the light --light picked.
      if (config.camera >= moved.cameras.size()) moved.cameras.push_back(scene.cameras[config.camera]);
      choose_light(moved, a.light);
      scene = std::move(moved);
    }
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
    print_frame_warnings(a.scene, result->warnings, chosen_light, warned);
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
  if (top.batch.empty() && top.scenes.size() > 1) {
    auto needs_scene = [&](const std::string& pattern, const char* option) {
      if (!pattern.empty() && !has_scene_field(pattern))
        throw CliError(option, "several scenes would write to the same file: put {scene} in the name");
    };
    needs_scene(top.out, "--out");
    needs_scene(top.maps, "--maps");
    needs_scene(top.aliasing, "--aliasing");
    needs_scene(top.aov_out, "--aov-out");
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
    nlohmann::json job_scenes = nlohmann::json::array();  // the whole run's, so that shards of two runs differ
    for (const auto& job : jobs) job_scenes.push_back(job.second.scene);
    print_json({{"command", "render"},
                {"batch", top.batch.empty() ? nlohmann::json(nullptr) : nlohmann::json(top.batch)},
                {"jobs_total", jobs.size()},
                {"job_scenes", job_scenes},
                {"shard", {{"index", shard.index}, {"count", shard.count}}},
                {"jobs", done},
                {"summary", {{"jobs", done.size()}, {"frames", frames}, {"wall_ms", watch.ms()}}}});
  }
  return 0;
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
  return {app, [app, args] {
            // A batch's jobs are its lines: an option given beside --batch would apply to none of them.
            if (!args->batch.empty())
              for (const CLI::Option* o : app->get_options())
                if (o->count() > 0 && !o->get_positional() && o->get_name() != "--batch" &&
                    o->get_name() != "--shard" && o->get_name() != "--json")
                  throw CliError(o->get_name(), "does not apply to a --batch run: give it on each line of " +
                                                    args->batch + " (beside --batch only --shard and --json)");
            return run_render(*args);
          }};
}

SHADOWLAB_ISA_END
}  // namespace cli
