// `shadowlab render-merge SHARD.json...`: joins the `render --json` documents of a batch's shards (`--shard I/N`,
// one per machine or array task) into the document one unsharded run prints: every shard of the same batch
// present once, jobs in batch order, the summary added up. Written to --out, or printed.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/json_output.h"
#include "scenes/io/atomic_write.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out;
};

nlohmann::json read_doc(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec) || !in) throw CliError(file, "cannot be read (no such file?)");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw CliError(file, "is not a JSON document");
  if (j.value("command", "") != "render") throw CliError(file, "is not the output of `shadowlab render --json`");
  for (const char* key : {"jobs_total", "shard", "jobs", "summary"})
    if (!j.contains(key)) throw CliError(file, std::string("has no \"") + key + "\"");
  return j;
}

int run_merge(const MergeArgs& a) {
  if (!a.out.empty()) check_output_dir(a.out, "--out");
  std::vector<nlohmann::json> docs;
  for (const std::string& f : a.shards) docs.push_back(read_doc(f));
  const nlohmann::json& first = docs.front();
  const size_t count = first["shard"].value("count", size_t(0));
  if (count != docs.size())
    throw CliError(a.shards[0], "belongs to a run of " + std::to_string(count) + " shards, " +
                                    std::to_string(docs.size()) + " given");
  std::vector<bool> seen(count, false);
  nlohmann::json jobs = nlohmann::json::array();
  size_t frames = 0;
  double wall_ms = 0;
  for (size_t i = 0; i < docs.size(); ++i) {
    const nlohmann::json& d = docs[i];
    if (d["batch"] != first["batch"] || d["jobs_total"] != first["jobs_total"] || d["shard"]["count"] != count)
      throw CliError(a.shards[i], "belongs to another run than " + a.shards[0] + " (batch, jobs or shard count differ)");
    const size_t index = d["shard"].value("index", count);
    if (index >= count) throw CliError(a.shards[i], "has no valid shard index");
    if (seen[index]) throw CliError(a.shards[i], "repeats shard " + std::to_string(index));
    seen[index] = true;
    for (const auto& job : d["jobs"]) {
      jobs.push_back(job);
      frames += job.at("frames").size();
    }
    wall_ms += d["summary"].value("wall_ms", 0.0);
  }
  std::stable_sort(jobs.begin(), jobs.end(), [](const nlohmann::json& x, const nlohmann::json& y) {
    return x.at("index").get<size_t>() < y.at("index").get<size_t>();
  });
  if (jobs.size() != first["jobs_total"].get<size_t>())
    throw CliError(a.shards[0], "the shards hold " + std::to_string(jobs.size()) + " jobs of " +
                                    std::to_string(first["jobs_total"].get<size_t>()));
  nlohmann::json merged = {{"command", "render"},
                           {"batch", first["batch"]},
                           {"jobs_total", first["jobs_total"]},
                           {"shard", {{"index", 0}, {"count", 1}}},
                           {"merged_from", count},
                           {"jobs", jobs},
                           {"summary", {{"jobs", jobs.size()}, {"frames", frames}, {"wall_ms", wall_ms}}}};
  if (a.out.empty()) {
    print_json(merged);
  } else {
    merged["shadowlab"] = version_json();
    const std::string text = merged.dump(2) + "\n";
    scenes::io::write_atomically(a.out, [&](const std::filesystem::path& tmp) {
      scenes::io::write_bytes(tmp, text.data(), text.size());
    });
  }
  return 0;
}

}  // namespace

Command add_render_merge_command(CLI::App& parent) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* app = parent.add_subcommand(
      "render-merge", "Join the --json documents of a render batch's shards into the unsharded run's document");
  app->add_option("shards", args->shards, "Every shard's `render --json` output")->required();
  app->add_option("--out", args->out, "Write the merged document here (default: print it)");
  return {app, [args] { return run_merge(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
