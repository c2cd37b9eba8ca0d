// `shadowlab check MANIFEST [--update]`: regression tests for users' own scenes. The manifest (JSON, documented
// in docs/cli.md) lists entries, each a scene with render options, whose frame (and, with "maps": true, every
// shadow map) is compared with the goldens stored beside the manifest: exactly by default, or within a per-entry
// tolerance and fail-over. Failures get colour-mapped difference images; a summary table (or --json) follows.
// Exit 0: all pass; 1: some differ; 2: an error (bad manifest, a render that fails, a missing golden).
// --update renders every entry and stores its outputs as the new goldens, all together.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/image_compare.h"
#include "cli/json_output.h"
#include "cli/render_line.h"
#include "scenes/builtin_scenes.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace fs = std::filesystem;

struct CheckArgs {
  std::string manifest, diff_dir;
  bool update = false, json = false;
};

struct Entry {
  std::string name, scene;
  std::vector<std::string> args;
  bool maps = false;
  double tolerance = 0.0;
  FailOver fail_over;
};

struct Manifest {
  fs::path dir;       // the manifest's folder: relative paths start here
  fs::path goldens;   // where the goldens live
  std::vector<Entry> entries;
};

// A name that is safe as a file name and unique in the manifest.
bool good_name(const std::string& n) {
  if (n.empty() || n.size() > 128 || n[0] == '.') return false;
  for (char c : n)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  return true;
}

Manifest read_manifest(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!fs::is_regular_file(file, ec) || !in) throw CliError(file, "cannot be read (no such file?)");
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw CliError(file, "is not a JSON object");
  for (const auto& [key, value] : j.items())
    if (key != "goldens" && key != "entries") throw CliError(file + ": " + key, "unknown field (known: goldens, entries)");
  Manifest m;
  m.dir = fs::path(file).parent_path();
  if (m.dir.empty()) m.dir = ".";
  const nlohmann::json goldens = j.value("goldens", nlohmann::json("goldens"));
  if (!goldens.is_string() || goldens.get<std::string>().empty())
    throw CliError(file + ": goldens", "expected a folder name");
  m.goldens = m.dir / goldens.get<std::string>();
  if (!j.contains("entries") || !j["entries"].is_array() || j["entries"].empty())
    throw CliError(file + ": entries", "expected a non-empty array of entries");
  std::set<std::string> names;
  for (size_t i = 0; i < j["entries"].size(); ++i) {
    const nlohmann::json& e = j["entries"][i];
    const std::string where = file + ": entries[" + std::to_string(i) + "]";
    if (!e.is_object()) throw CliError(where, "expected an object");
    for (const auto& [key, value] : e.items())
      if (key != "name" && key != "scene" && key != "args" && key != "maps" && key != "tolerance" && key != "fail_over")
        throw CliError(where + "." + key, "unknown field (known: name, scene, args, maps, tolerance, fail_over)");
    Entry x;
    if (!e.contains("name") || !e["name"].is_string() || !good_name(e["name"].get<std::string>()))
      throw CliError(where + ".name", "expected a file-name-safe name (letters, digits, '-', '_', '.')");
    x.name = e["name"].get<std::string>();
    if (!names.insert(x.name).second) throw CliError(where + ".name", "'" + x.name + "' is used twice");
    if (!e.contains("scene") || !e["scene"].is_string() || e["scene"].get<std::string>().empty())
      throw CliError(where + ".scene", "expected a scene file (relative to the manifest) or a built-in name");
    x.scene = e["scene"].get<std::string>();
    // A scene file is relative to the manifest; a built-in name stays as it is.
    // A file, not a folder: a folder beside the manifest named like a built-in scene does not hide the scene.
    const fs::path beside = m.dir / x.scene;
    if (fs::is_regular_file(beside, ec) || (fs::exists(beside, ec) && !scenes::is_builtin_scene(x.scene)))
      x.scene = beside.string();
    if (e.contains("args")) {
      if (!e["args"].is_array()) throw CliError(where + ".args", "expected an array of strings");
      for (const auto& w : e["args"]) {
        if (!w.is_string()) throw CliError(where + ".args", "expected an array of strings");
        const std::string word = w.get<std::string>();
        for (const char* own : {"--out", "--maps", "--json", "--batch", "--shard", "--frames"})
          if (word == own || word.rfind(std::string(own) + "=", 0) == 0)
            throw CliError(where + ".args", std::string(own) + " is set by check itself");
        x.args.push_back(word);
      }
    }
    if (e.contains("maps")) {
      if (!e["maps"].is_boolean()) throw CliError(where + ".maps", "expected true or false");
      x.maps = e["maps"].get<bool>();
    }
    if (e.contains("tolerance")) {
      if (!e["tolerance"].is_number() || !(e["tolerance"].get<double>() >= 0.0))
        throw CliError(where + ".tolerance", "expected a number >= 0");
      x.tolerance = e["tolerance"].get<double>();
    }
    if (e.contains("fail_over")) {
      const nlohmann::json& f = e["fail_over"];
      x.fail_over = parse_fail_over(f.is_string() ? f.get<std::string>() : f.dump(), where + ".fail_over");
    }
    m.entries.push_back(std::move(x));
  }
  return m;
}

// A fresh private folder for one run's renders, removed at the end.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);
    for (int k = 0; k < 1000 && path.empty(); ++k) {
      const fs::path p = base / ("shadowlab-check-" + std::to_string(getpid()) + "-" + std::to_string(k));
      if (fs::create_directory(p, ec)) path = p;
    }
    if (path.empty()) throw CliError("check", "cannot create a scratch folder in " + base.string());
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// What one entry rendered: the frame and its maps, by the file names their goldens have.
struct Rendered {
  fs::path frame;
  std::vector<fs::path> maps;  // EXR files, golden name = "<entry>-maps/<file name>"
};

// The render line of an entry, its outputs in `scratch`.
std::vector<std::string> entry_words(const Entry& e, const fs::path& scratch) {
  std::vector<std::string> words = {e.scene};
  words.insert(words.end(), e.args.begin(), e.args.end());
  words.insert(words.end(), {"--out", (scratch / (e.name + ".png")).string()});
  if (e.maps) words.insert(words.end(), {"--maps", (scratch / (e.name + "-maps")).string()});
  return words;
}

Rendered render_entry(const Entry& e, const fs::path& scratch) {
  render_line(entry_words(e, scratch), "entry " + e.name);
  const fs::path out = scratch / (e.name + ".png"), maps = scratch / (e.name + "-maps");
  Rendered r{out, {}};
  std::error_code ec;
  if (e.maps && fs::exists(maps, ec))
    for (const auto& f : fs::directory_iterator(maps)) r.maps.push_back(f.path());
  std::sort(r.maps.begin(), r.maps.end());
  return r;
}

int run_check(const CheckArgs& a) {
  const Manifest m = read_manifest(a.manifest);
  const fs::path diff_dir = a.diff_dir.empty() ? m.dir / "check-diffs" : fs::path(a.diff_dir);
  ScratchDir scratch;
  Progress progress;
  nlohmann::json results = nlohmann::json::array();
  size_t failed = 0, passed = 0;
  // Every entry's line is checked before the first renders (and before goldens are looked for).
  for (const Entry& e : m.entries) check_render_line(entry_words(e, scratch.path), "entry " + e.name);

  if (a.update) {
    // Every entry renders first; then every golden is replaced together (and stale maps of an entry removed).
    // The folders the batch makes go again if an entry fails.
    scenes::io::WriteBatch batch;
    std::error_code ec;
    make_folder(batch, m.goldens, m.goldens.string());
    std::vector<fs::path> stale;
    for (const Entry& e : m.entries) {
      progress.update("rendering " + e.name);
      const Rendered r = render_entry(e, scratch.path);
      auto stage_copy = [&](const fs::path& from, const fs::path& to) {
        make_folder(batch, to.parent_path(), to.parent_path().string());
        batch.stage(to, [&](const fs::path& tmp) {
          // Read whole and written with write_bytes, which checks every write and the flush (a full disk is an
          // error naming the golden, not a filesystem_error quoting the scratch files).
          std::ifstream in(from, std::ios::binary);
          const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
          if (!in && !in.eof()) throw scenes::io::IoError(tmp, "cannot read the rendered " + from.filename().string());
          scenes::io::write_bytes(tmp, bytes.data(), bytes.size());
        });
      };
      stage_copy(r.frame, m.goldens / (e.name + ".png"));
      std::set<std::string> kept;
      for (const fs::path& map : r.maps) {
        stage_copy(map, m.goldens / (e.name + "-maps") / map.filename());
        kept.insert(map.filename().string());
      }
      const fs::path golden_maps = m.goldens / (e.name + "-maps");
      if (fs::exists(golden_maps, ec))
        for (const auto& f : fs::directory_iterator(golden_maps))
          if (!kept.count(f.path().filename().string())) stale.push_back(f.path());
      results.push_back({{"name", e.name}, {"status", "updated"}, {"maps", r.maps.size()}});
    }
    batch.commit();
    for (const fs::path& f : stale) fs::remove(f, ec);
  } else {
    std::error_code ec;
    // An entry never updated is an error (exit 2), before anything renders; a map missing from a golden maps
    // folder that exists is a difference (a map the render now writes, exit 1).
    for (const Entry& e : m.entries) {
      const fs::path frame = m.goldens / (e.name + ".png"), maps = m.goldens / (e.name + "-maps");
      if (!fs::exists(frame, ec))
        throw CliError(frame.string(), "no golden for entry " + e.name + " (run check --update to create it)");
      if (e.maps && !fs::is_directory(maps, ec))
        throw CliError(maps.string(), "no golden maps for entry " + e.name + " (run check --update to create them)");
    }
    for (const Entry& e : m.entries) {
      progress.update("checking " + e.name);
      const Rendered r = render_entry(e, scratch.path);
      nlohmann::json files = nlohmann::json::array();
      bool differs = false;
      auto compare = [&](const fs::path& golden, const fs::path& fresh, const std::string& label) {
        nlohmann::json c;
        if (!fs::exists(golden, ec)) {
          c = {{"file", label}, {"status", "no golden"}};
          differs = true;
        } else {
          const fs::path diff = diff_dir / (label + ".diff.png");
          nlohmann::json cmp = compare_images(golden.string(), fresh.string(), {e.tolerance, "", ""});
          const bool over = over_limit(cmp, e.fail_over);
          if (over) {  // only failures get a difference image
            fs::create_directories(diff.parent_path(), ec);
            cmp = compare_images(golden.string(), fresh.string(), {e.tolerance, "", diff.string()});
          }
          differs |= over;
          c = {{"file", label},       {"status", over ? "differs" : "pass"}, {"max", cmp["max"]},
               {"over", cmp["over"]}, {"pixels", cmp["pixels"]},             {"psnr", cmp["psnr"]},
               {"diff_image", over ? nlohmann::json(diff.string()) : nlohmann::json(nullptr)}};
        }
        files.push_back(c);
      };
      compare(m.goldens / (e.name + ".png"), r.frame, e.name);
      std::set<std::string> fresh_maps;
      for (const fs::path& map : r.maps) {
        fresh_maps.insert(map.filename().string());
        compare(m.goldens / (e.name + "-maps") / map.filename(), map, e.name + "-maps/" + map.filename().string());
      }
      const fs::path golden_maps = m.goldens / (e.name + "-maps");
      if (e.maps && fs::exists(golden_maps, ec))
        for (const auto& f : fs::directory_iterator(golden_maps))
          if (!fresh_maps.count(f.path().filename().string())) {
            files.push_back({{"file", e.name + "-maps/" + f.path().filename().string()}, {"status", "not rendered"}});
            differs = true;
          }
      (differs ? failed : passed) += 1;
      results.push_back({{"name", e.name},
                         {"status", differs ? "differs" : "pass"},
                         {"tolerance", e.tolerance},
                         {"files", files}});
    }
  }

  if (a.json) {
    print_json({{"command", "check"},
                {"manifest", a.manifest},
                {"update", a.update},
                {"entries", results},
                {"summary", {{"entries", results.size()}, {"passed", passed}, {"differ", failed}}}});
  } else if (a.update) {
    for (const auto& r : results)
      std::printf("%-32s updated (frame and %zu maps)\n", r["name"].get<std::string>().c_str(), r["maps"].get<size_t>());
    std::printf("%zu goldens written to %s\n", results.size(), m.goldens.string().c_str());
  } else {
    std::printf("%-40s %-12s %12s %10s %10s\n", "file", "status", "max", "over", "PSNR dB");
    for (const auto& r : results)
      for (const auto& f : r["files"]) {
        auto num = [](const nlohmann::json& v, const char* fmt) {
          if (v.is_null()) return std::string("-");
          char buf[32];
          std::snprintf(buf, sizeof buf, fmt, v.get<double>());
          return std::string(buf);
        };
        std::printf("%-40s %-12s %12s %10s %10s\n", f["file"].get<std::string>().c_str(),
                    f["status"].get<std::string>().c_str(), num(f.value("max", nlohmann::json()), "%.6g").c_str(),
                    f.contains("over") ? std::to_string(f["over"].get<size_t>()).c_str() : "-",
                    f.contains("psnr") ? (f["psnr"].is_null() ? "inf" : num(f["psnr"], "%.2f").c_str()) : "-");
        if (f.contains("diff_image") && !f["diff_image"].is_null())
          std::printf("  difference image: %s\n", f["diff_image"].get<std::string>().c_str());
      }
    std::printf("%zu of %zu entries pass%s\n", passed, results.size(), failed ? "; run with --update to accept" : "");
  }
  return failed ? 1 : 0;
}

}  // namespace

Command add_check_command(CLI::App& parent) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* app = parent.add_subcommand(
      "check", "Regression-test scenes against stored goldens (exit 0 pass, 1 differences, 2 errors)");
  app->add_option("manifest", args->manifest, "The manifest (JSON): goldens folder and entries, see docs/cli.md")
      ->required();
  app->add_flag("--update", args->update, "Render every entry and store its outputs as the new goldens");
  app->add_option("--diff-dir", args->diff_dir,
                  "Where difference images of failures go (default: check-diffs beside the manifest)");
  app->add_flag("--json", args->json, "Print JSON (docs/cli/check.schema.json) instead of the table");
  return {app, [args] { return run_check(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
