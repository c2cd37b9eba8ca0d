// Option parsing, scene lookup and terminal progress shared by the commands (see cli_common.h).
#include "cli/cli_common.h"
#include "cli/light_choice.h"

#include "scenes/io/io_error.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <system_error>

#include "raster/limits.h"
#include "scenes/builtin_scenes.h"
#include "scenes/scene_build.h"
#include "scenes/stage.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

bool parse_int(std::string_view s, long long& out) {
  if (s.empty()) return false;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && ptr == s.data() + s.size();
}

bool parse_float(std::string_view s, float& out) {
  // std::from_chars for float is not in every libstdc++; strtof on a copy is exact and portable.
  const std::string copy(s);
  if (copy.empty() || std::isspace(static_cast<unsigned char>(copy[0]))) return false;
  char* end = nullptr;
  out = std::strtof(copy.c_str(), &end);
  return end == copy.c_str() + copy.size() && std::isfinite(out);
}

}  // namespace

Size2 parse_size(const std::string& text, const std::string& option) {
  const size_t x = text.find_first_of("xX");
  long long w = 0, h = 0;
  if (x == std::string::npos || !parse_int(std::string_view(text).substr(0, x), w) ||
      !parse_int(std::string_view(text).substr(x + 1), h))
    throw CliError(option, "expected WIDTHxHEIGHT, got '" + text + "'");
  if (w < 1 || w > raster::kMaxTargetSize)
    throw CliError(option, "width " + std::to_string(w) + " is outside 1.." + std::to_string(raster::kMaxTargetSize));
  if (h < 1 || h > raster::kMaxTargetSize)
    throw CliError(option,
                   "height " + std::to_string(h) + " is outside 1.." + std::to_string(raster::kMaxTargetSize));
  return {int(w), int(h)};
}

std::pair<float, float> parse_float_pair(const std::string& text, const std::string& option, std::string_view format) {
  const size_t comma = text.find(',');
  float a = 0, b = 0;
  if (comma == std::string::npos || !parse_float(std::string_view(text).substr(0, comma), a) ||
      !parse_float(std::string_view(text).substr(comma + 1), b))
    throw CliError(option, "expected two finite numbers separated by a comma (" + std::string(format) + "), got '" + text + "'");
  return {a, b};
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void add_threads_option(CLI::App& app, std::optional<int>& threads) {
  app.add_option_function<int>("--threads", [&threads](const int& v) { threads = v; },
                               "Worker threads (0: inline; default: all cores)");
}

int check_threads(const std::optional<int>& threads) {
  if (!threads) return -1;
  if (*threads < 0 || *threads > kMaxThreads)
    throw CliError("--threads", std::to_string(*threads) + " is outside 0.." + std::to_string(kMaxThreads) +
                                    " (leave it out for all cores)");
  return *threads;
}

void make_folder(scenes::io::WriteBatch& batch, const std::filesystem::path& dir, const std::string& where) {
  try {
    batch.create_directories(dir);
  } catch (const scenes::io::IoError& e) {
    throw CliError(where, e.reason());  // "cannot create the folder F (why)"
  }
}

void check_output_dir(const std::string& file, const std::string& option) {
  std::filesystem::path path(file);
  if (!path.has_filename()) path = path.parent_path();  // "out/" names the folder out, made in "."
  const std::filesystem::path parent = path.parent_path();
  std::error_code ec;
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
    throw CliError(option, "directory " + parent.string() + " does not exist");
}

namespace {

bool is_model_file(const std::filesystem::path& p) {
  const std::string e = lower_extension(p);
  return e == ".gltf" || e == ".glb";
}

}  // namespace

void check_scene_exists(const std::string& name) {
  const std::filesystem::path path(name);
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec) || scenes::is_builtin_scene(name)) return;
  if (std::filesystem::exists(path, ec)) throw CliError(name, "not a regular file");
  if (name.find('/') != std::string::npos || path.has_extension()) throw CliError(name, "no such file");
  scenes::builtin_scene(name);  // throws `NAME: unknown built-in scene (known: ...)`
}

namespace {

scenes::Scene load_any(const std::string& name, const scenes::StageOptions* stage, std::vector<std::string>* notes) {
  const std::filesystem::path path(name);
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    if (stage && is_model_file(path)) {
      scenes::StagedScene staged = scenes::load_model_staged(path, *stage);
      if (notes) notes->insert(notes->end(), staged.notes.begin(), staged.notes.end());
      return std::move(staged.scene);
    }
    return scenes::load_scene(path);
  }
  // A folder named like a built-in scene (`eval tutorial --out tutorial` makes one) does not hide the scene.
  check_scene_exists(name);
  return scenes::builtin_scene(name);
}

}  // namespace

void print_notes(const std::vector<std::string>& notes) {
  for (const std::string& n : notes) std::fprintf(stderr, "shadowlab: note: %s\n", n.c_str());
}

void print_frame_warnings(const std::string& scene, const std::vector<std::string>& warnings,
                          std::optional<size_t> chosen, std::set<std::string>& said) {
  for (const std::string& w : warnings) {
    const std::string line = scene + ": " + light_field(w, chosen);
    if (said.insert(line).second) std::fprintf(stderr, "shadowlab: warning: %s\n", line.c_str());
  }
}

scenes::Scene load_scene_or_builtin(const std::string& name, const scenes::StageOptions* stage,
                                    std::vector<std::string>* notes) {
  scenes::Scene scene = load_any(name, stage, notes);
  std::set<std::string> said;
  for (const std::string& w : scene.warnings)
    if (said.insert(w).second) std::fprintf(stderr, "shadowlab: warning: %s\n", w.c_str());
  return scene;
}

Progress::Progress() : enabled_(isatty(STDERR_FILENO) == 1) {
  if (!enabled_) return;
  // One small thread redraws the line a few times a second once the work has run for a second: short runs
  // print nothing, long ones show what they are doing and for how long.
  ticker_ = std::thread([this] {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      wake_.wait_for(lock, std::chrono::milliseconds(250));
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (stop_ || s < 1.0 || line_.empty()) continue;
      std::fprintf(stderr, "\r\033[K%s (%.0f s)", line_.c_str(), s);
      std::fflush(stderr);
      dirty_ = true;
    }
  });
}

Progress::~Progress() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  ticker_.join();
  if (dirty_) std::fputs("\r\033[K", stderr);  // the progress line disappears
}

void Progress::update(const std::string& line) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  line_ = line;
}

SHADOWLAB_ISA_END
}  // namespace cli
