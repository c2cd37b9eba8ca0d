// A render job's arguments: RenderArgs, the render options that fill it (the shadow settings' from
// shadow_options.h), the checks a job passes before anything renders, and the jobs of a batch file
// or a command line given as words. cmd_render.cpp renders them.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/look_options.h"
#include "cli/shadow_options.h"
#include "scenes/frame/surface_record.h"
#include "scenes/stage.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

struct RenderArgs {
  std::vector<std::string> scenes;
  std::string scene;  // the one scene of a job
  std::string technique, filter, bias, size = "1280x720", maps, out = "frame.png", aliasing;
  std::string aov, aov_out;  // --aov position,normal,visibility,depth  --aov-out FILE.exr
  std::optional<long long> shadow_size;  // given or not (a plain value: jobs outlive the parser that filled them)
  std::string shadow_size_text;         // as given, for messages
  std::optional<int> threads;  // --threads, left out for all cores
  int frames = 1;
  bool stats = false;
  std::optional<bool> cull_front;  // --cull-front / --no-cull-front
  bool animate = false;            // --animate: rebuild an animated built-in scene per frame
  std::optional<double> fps;        // --fps (with --animate; default 24): frame K is at time K / fps
  ShadowOverrides shadow;      // depth format, Poisson, bias values, technique parameters (shadow_options.h)
  bool ground = true;         // --ground / --no-ground: a plane under a bare glTF model (scenes/stage.h)
  std::string sun, up = "y";  // --sun AZ,EL for a bare model; --up y|z: the model's up axis
  std::string camera;         // --camera NAME|INDEX|orbit:AZ,EL[,DIST]
  std::string light;          // --light NAME|INDEX: that light alone
  LookArgs look;              // --exposure, --tonemap, --background
  bool json = false;          // --json: one document on stdout instead of text
  std::string batch, shard;   // --batch FILE, --shard I/N (top level only)
};

// Adds every render option (scene arguments included) to `command`, filling `args`.
void add_render_options(CLI::App& command, const std::shared_ptr<RenderArgs>& args);
// The command-line option of a library field named at the start of a FrameError (`map_size` -> --shadow-size),
// or the field itself.
std::string option_for_field(const std::string& field);
// --aov's comma-separated channel names (every channel when only --aov-out is given); empty without either.
std::vector<frame::AovChannel> parse_aov_list(const std::string& list, const std::string& out);
// Every check of a job's arguments that needs no rendering, so a bad job (or batch line) fails before any work.
void check_job(const RenderArgs& a);

// --up's value as the staging's axis: y, z, -y or -z; anything else is a CliError on --up.
scenes::StageOptions::Up up_axis(const std::string& up);
// One job's arguments from `parse` (which runs a parser holding the render options over a command line): one
// scene, and none of the top-level-only options. Errors are CliErrors on `where`.
RenderArgs parse_job(const std::string& where, const std::function<void(CLI::App&)>& parse);
// The same from a command line's words (the words after `shadowlab render`).
RenderArgs parse_line(const std::vector<std::string>& args, const std::string& where);
// A batch file's jobs, with `file:line` as their place.
std::vector<std::pair<std::string, RenderArgs>> read_batch(const std::string& file);
// No two jobs of a run write the same file or maps folder.
void check_distinct_outputs(const std::vector<std::pair<std::string, RenderArgs>>& jobs);

SHADOWLAB_ISA_END
}  // namespace cli
