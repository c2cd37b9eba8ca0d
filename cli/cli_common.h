// What every shadowlab command shares: the one error type for bad options (printed as
// `shadowlab: error: WHERE: what`), option parsers for sizes and counts, scene loading by file or built-in
// name, terminal-only progress, and a stopwatch.
#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "scenes/io/atomic_write.h"

#include "scenes/scene.h"
#include "scenes/stage.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// Bad input found by the CLI itself. what() is `WHERE: what is wrong`; WHERE is an option name or a file.
class CliError : public std::runtime_error {
 public:
  CliError(const std::string& where, const std::string& what) : std::runtime_error(where + ": " + what) {}
};

// A subcommand as main() sees it: its parser, and what to run once it has parsed. run() returns the exit code.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_render_command(CLI::App& parent);
Command add_shadowmap_command(CLI::App& parent);
Command add_inspect_command(CLI::App& parent);
Command add_diff_command(CLI::App& parent);
Command add_eval_command(CLI::App& parent);
Command add_eval_merge_command(CLI::App& parent);
Command add_list_command(CLI::App& parent);
Command add_render_merge_command(CLI::App& parent);
Command add_check_command(CLI::App& parent);
Command add_scene_command(CLI::App& parent);

struct Size2 {
  int width = 0, height = 0;
};

// "WxH" with both sides in 1..raster::kMaxTargetSize; `option` names the option in errors.
Size2 parse_size(const std::string& text, const std::string& option);
// "A,B" as two finite floats; `format` names the two in the error ("AZ,EL").
std::pair<float, float> parse_float_pair(const std::string& text, const std::string& option, std::string_view format);

// A scene file (JSON, .gltf, .glb) when `name` names an existing file, else a built-in scene. A name that looks
// like a path (a '/' or an extension) but is no file is reported as a missing file. With `stage`, a .gltf/.glb
// model is staged (scenes/stage.h: a sun, a ground and a camera where the file has none) and what was added is
// appended to `notes` (print_notes() says them once the command's other checks have passed, so an error stays
// the only line). The scene's import warnings are printed once each as `shadowlab: warning: ...`.
scenes::Scene load_scene_or_builtin(const std::string& name, const scenes::StageOptions* stage = nullptr,
                                    std::vector<std::string>* notes = nullptr);
// Each note on stderr as `shadowlab: note: ...`.
void print_notes(const std::vector<std::string>& notes);
// A frame's warnings (frame::Frame::warnings) on stderr as `shadowlab: warning: SCENE: ...`, those not in `said`
// yet (which they join), so that a sequence or a sweep says each once. With --light (`chosen`: the light's place
// in the file, light_choice.h) they name the light there, as errors do.
void print_frame_warnings(const std::string& scene, const std::vector<std::string>& warnings,
                          std::optional<size_t> chosen, std::set<std::string>& said);

// A progress line on stderr for work that runs over a second, only when stderr is a terminal (silent in scripts
// and CI): update() sets what the work is doing; a small thread redraws it with the elapsed time four times a
// second from the first second on; the line is erased at the end.
class Progress {
 public:
  Progress();
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(const std::string& line);

 private:
  bool enabled_ = false;
  bool dirty_ = false;
  bool stop_ = false;
  std::string line_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
};

// Milliseconds since construction.
class Stopwatch {
 public:
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The --threads option, left out for all cores, 0 (inline) up to kMaxThreads given; anything else is a CliError
// on the option (issue 23: 10^8 threads ended in "out of memory"). check_threads returns what raster::Renderer
// takes (-1 for all cores).
inline constexpr int kMaxThreads = 1024;
void add_threads_option(CLI::App& app, std::optional<int>& threads);
int check_threads(const std::optional<int>& threads);

// A scene argument names a regular file or a built-in scene; otherwise a CliError naming it (what loading it
// would say), so that a run with several scenes fails before the first renders.
void check_scene_exists(const std::string& name);

// Fails early (before any long work) when the folder an output goes to does not exist. A name ending in a
// separator ("out/", for outputs that are folders) names that folder, so its parent is the one checked.
void check_output_dir(const std::string& file, const std::string& option);

// batch.create_directories(dir), its IoError a CliError on `where` (batch: it removes the folders again unless
// committed).
void make_folder(scenes::io::WriteBatch& batch, const std::filesystem::path& dir, const std::string& where);

// A file's lower-case extension with its dot (".exr"), for format decisions.
std::string lower_extension(const std::filesystem::path& path);

SHADOWLAB_ISA_END
}  // namespace cli
