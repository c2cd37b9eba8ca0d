// `shadowlab eval-merge --out DIR SHARD_DIR...`: the reports of the shards of one sweep (`eval --shard I/N`, run by
// any batch scheduler) combined into one: every shard of the same scene, frame, reference and scoring present
// exactly once, results in sweep order, error maps copied. Checked completely before anything is written.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/eval_report.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace fs = std::filesystem;

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out = "eval";
};

nlohmann::json read_report(const fs::path& dir) {
  const fs::path file = dir / "eval.json";
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CliError(file.string(), "cannot be read (not an eval output directory?)");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw CliError(file.string(), "is not a JSON object");
  for (const char* key : {"scene", "frame", "reference", "scoring", "sweep", "results"})
    if (!j.contains(key)) throw CliError(file.string(), std::string("has no \"") + key + "\"");
  return j;
}

int run_merge(const MergeArgs& a) {
  if (a.shards.empty()) throw CliError("eval-merge", "no shard directories given");
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec)) throw CliError("--out", a.out + " exists and is not a directory");
  check_output_dir(a.out, "--out");

  std::vector<nlohmann::json> reports;
  for (const std::string& d : a.shards) reports.push_back(read_report(d));
  const nlohmann::json& first = reports.front();
  const size_t count = first["sweep"].value("shards", size_t(0));
  if (count != a.shards.size())
    throw CliError((fs::path(a.shards[0]) / "eval.json").string(),
                   "belongs to a sweep of " + std::to_string(count) + " shards, " + std::to_string(a.shards.size()) +
                       " given");
  std::vector<bool> seen(count, false);
  nlohmann::json results = nlohmann::json::array();
  for (size_t i = 0; i < reports.size(); ++i) {
    const nlohmann::json& r = reports[i];
    const std::string file = (fs::path(a.shards[i]) / "eval.json").string();
    // The same sweep: scene, frame, reference (the same rays), scoring, combination and shard counts.
    for (const char* key : {"scene", "frame", "scoring"})
      if (r[key] != first[key]) throw CliError(file, std::string("its \"") + key + "\" differs from the first shard's");
    for (const char* key : {"triangles", "rays", "epsilon"})
      if (r["reference"][key] != first["reference"][key])
        throw CliError(file, std::string("its reference's \"") + key + "\" differs from the first shard's");
    if (r["sweep"]["combinations"] != first["sweep"]["combinations"] || r["sweep"]["shards"] != first["sweep"]["shards"])
      throw CliError(file, "belongs to another sweep than the first shard");
    const size_t index = r["sweep"].value("shard", count);
    if (index >= count) throw CliError(file, "has no valid shard index");
    if (seen[index]) throw CliError(file, "repeats shard " + std::to_string(index));
    seen[index] = true;
    for (const auto& row : r["results"]) results.push_back(row);
  }
  std::stable_sort(results.begin(), results.end(), [](const nlohmann::json& x, const nlohmann::json& y) {
    return std::make_pair(x.at("index").get<size_t>(), x.at("light").get<size_t>()) <
           std::make_pair(y.at("index").get<size_t>(), y.at("light").get<size_t>());
  });

  nlohmann::json merged = first;
  merged["sweep"] = {{"combinations", first["sweep"]["combinations"]}, {"shard", 0}, {"shards", 1}, {"merged_from", count}};
  merged["results"] = results;
  // Each shard's reference times, for the record (the rays are the same in every shard).
  nlohmann::json times = nlohmann::json::array();
  for (const auto& r : reports) times.push_back(r["reference"].value("rays_ms", 0.0));
  merged["reference"]["rays_ms_per_shard"] = times;

  // Each result's contact sheet from the shard that holds it.
  ContactSheets sheets;
  for (size_t s = 0; s < reports.size(); ++s)
    for (const auto& row : reports[s]["results"]) {
      const std::string label = row.at("combination").get<std::string>();
      if (sheets.count(label)) continue;
      const fs::path png = fs::path(a.shards[s]) / (label + ".png");
      std::ifstream in(png, std::ios::binary);
      if (!in) throw CliError(png.string(), "cannot be read (the shard's contact sheet for " + label + ")");
      sheets[label].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      if (in.bad()) throw CliError(png.string(), "cannot be read");
    }
  fs::create_directories(a.out, ec);
  if (ec) throw CliError("--out", "cannot create directory " + a.out + " (" + ec.message() + ")");
  write_eval_report(a.out, merged, sheets);
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
