// `shadowlab eval-merge --out DIR SHARD_DIR...`: the reports of the shards of one sweep (`eval --shard I/N`, run by
// any batch scheduler) combined into one: every shard of the same scene, frame, reference and scoring present
// exactly once, results in sweep order, error maps copied. Checked completely before anything is written.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/eval_report.h"
#include "scenes/io/atomic_write.h"
#include "scenes/json_in.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace fs = std::filesystem;

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out = "eval";
};

constexpr uint32_t kMost = 1u << 30;

// One shard's report, the fields the merge reads checked where they are read: a missing or mistyped one is named
// with the file (`s0/eval.json: sweep.shard: expected ...`).
struct ShardReport {
  std::string file;
  nlohmann::json doc;
  uint32_t shard = 0, shards = 0;
};

ShardReport read_report(const fs::path& dir) {
  ShardReport r;
  r.file = (dir / "eval.json").string();
  std::ifstream in(r.file, std::ios::binary);
  if (!in) throw CliError(r.file, "cannot be read (not an eval output directory?)");
  std::stringstream text;
  text << in.rdbuf();
  r.doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (r.doc.is_discarded() || !r.doc.is_object()) throw CliError(r.file, "is not a JSON object");
  const scenes::JsonIn root(r.doc, "", r.file);
  // What the merge and the report it writes (eval.csv, eval.html) read.
  root.member("scene").string();
  root.member("shimmer");
  const scenes::JsonIn frame = root.member("frame");
  frame.member("width").integer(1, kMost);
  frame.member("height").integer(1, kMost);
  const scenes::JsonIn scoring = root.member("scoring");
  scoring.member("shadow_below").number();
  scoring.member("near_radius_pixels").number();
  const scenes::JsonIn reference = root.member("reference");
  reference.member("triangles").integer(0, UINT32_MAX);
  reference.member("rays").integer(0, UINT32_MAX);
  reference.member("epsilon").number();
  reference.member("rays_ms").number();
  const scenes::JsonIn sweep = root.member("sweep");
  const uint32_t combinations = sweep.member("combinations").integer(1, kMost);
  r.shards = sweep.member("shards").integer(1, kMost);
  r.shard = sweep.member("shard").integer(0, r.shards - 1);
  const std::vector<scenes::JsonIn> labels = sweep.member("labels").items();
  if (labels.size() != combinations)
    sweep.fail_at("labels", std::to_string(labels.size()) + " labels for " + std::to_string(combinations) +
                                " combinations");
  for (const scenes::JsonIn& label : labels) label.string();
  for (const scenes::JsonIn& row : root.member("results").items()) {
    for (const char* column : eval_columns()) row.member(column);
    const uint32_t index = row.member("index").integer(0, combinations - 1);
    row.member("light").integer(0, kMost);
    if (row.member("combination").string() != labels[index].string())
      row.fail_at("combination", "is not the sweep's combination " + std::to_string(index) + " (" +
                                     labels[index].string() + ")");
    if (index % r.shards != r.shard)
      row.fail_at("index", std::to_string(index) + " is not a combination of shard " + std::to_string(r.shard) +
                               "/" + std::to_string(r.shards));
  }
  return r;
}

// The sweep a report belongs to: its record without the shard's own index.
nlohmann::json sweep_of(const nlohmann::json& report) {
  nlohmann::json s = report["sweep"];
  s.erase("shard");
  return s;
}

int run_merge(const MergeArgs& a) {
  if (a.shards.empty()) throw CliError("eval-merge", "no shard directories given");
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec)) throw CliError("--out", a.out + " exists and is not a directory");
  check_output_dir(a.out, "--out");

  std::vector<ShardReport> shards;
  for (const std::string& d : a.shards) shards.push_back(read_report(d));
  const nlohmann::json& first = shards.front().doc;
  const size_t count = shards.front().shards;
  if (count != a.shards.size())
    throw CliError(shards.front().file, "belongs to a sweep of " + std::to_string(count) + " shards, " +
                                            std::to_string(a.shards.size()) + " given");
  std::vector<bool> seen(count, false);
  nlohmann::json results = nlohmann::json::array();
  std::vector<nlohmann::json> reports;
  for (const ShardReport& s : shards) {
    const nlohmann::json& r = s.doc;
    // The same sweep: scene, frame, reference (the same rays), scoring, shimmer, and the sweep itself (its
    // combinations in order, the light chosen, the cull-front override, the shard count).
    for (const char* key : {"scene", "frame", "scoring", "shimmer"})
      if (r[key] != first[key]) throw CliError(s.file, std::string("its \"") + key + "\" differs from the first shard's");
    for (const char* key : {"triangles", "rays", "epsilon"})
      if (r["reference"][key] != first["reference"][key])
        throw CliError(s.file, std::string("its reference's \"") + key + "\" differs from the first shard's");
    if (sweep_of(r) != sweep_of(first))
      throw CliError(s.file, "belongs to another sweep than the first shard (its combinations, light, cull-front "
                             "override, settings or shard count differ)");
    if (seen[s.shard]) throw CliError(s.file, "repeats shard " + std::to_string(s.shard));
    seen[s.shard] = true;
    for (const auto& row : r["results"]) results.push_back(row);
    reports.push_back(r);
  }
  std::stable_sort(results.begin(), results.end(), [](const nlohmann::json& x, const nlohmann::json& y) {
    return std::make_pair(x["index"].get<size_t>(), x["light"].get<size_t>()) <
           std::make_pair(y["index"].get<size_t>(), y["light"].get<size_t>());
  });

  nlohmann::json merged = first;
  merged["sweep"]["shard"] = 0;
  merged["sweep"]["shards"] = 1;
  merged["sweep"]["merged_from"] = count;
  merged["results"] = results;
  // Each shard's reference times, for the record (the rays are the same in every shard).
  nlohmann::json times = nlohmann::json::array();
  for (const auto& r : reports) times.push_back(r["reference"]["rays_ms"]);
  merged["reference"]["rays_ms_per_shard"] = times;

  // Each result's contact sheet from the shard that holds it.
  ContactSheets sheets;
  for (size_t s = 0; s < reports.size(); ++s)
    for (const auto& row : reports[s]["results"]) {
      const std::string label = row["combination"].get<std::string>();
      if (sheets.count(label)) continue;
      const fs::path png = fs::path(a.shards[s]) / (label + ".png");
      std::ifstream in(png, std::ios::binary);
      if (!in) throw CliError(png.string(), "cannot be read (the shard's contact sheet for " + label + ")");
      sheets[label].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      if (in.bad()) throw CliError(png.string(), "cannot be read");
    }
  // Made as eval makes it: removed again (when it was new and is empty) if the report cannot be written.
  scenes::io::WriteBatch out_folder;
  make_folder(out_folder, a.out, "--out");
  write_eval_report(a.out, merged, sheets);
  out_folder.commit();
  return 0;
}

}  // namespace

Command add_eval_merge_command(CLI::App& parent) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* app = parent.add_subcommand("eval-merge", "Combine the reports of the shards of one eval sweep");
  app->add_option("shards", args->shards, "The shards' output directories (each holds eval.json)")->required();
  app->add_option("--out", args->out, "Output directory for the merged eval.csv, eval.json and error maps");
  return {app, [args] { return run_merge(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
