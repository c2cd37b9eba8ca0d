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
#include "scenes/json_in.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out;
};

// One shard's document, its fields checked where they are read: a missing or mistyped one is named with the file
// (`a.json: shard.count: expected a whole number ...`).
struct ShardDoc {
  nlohmann::json batch;  // the batch file's name, or null for scene arguments
  nlohmann::json job_scenes;  // every job's scene, in batch order
  uint32_t jobs_total = 0, index = 0, count = 0;
  std::vector<nlohmann::json> jobs;
  std::vector<uint32_t> job_index;
  size_t frames = 0;
  double wall_ms = 0;
};

constexpr uint32_t kMost = 1u << 30;

ShardDoc read_doc(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec) || !in) throw CliError(file, "cannot be read (no such file?)");
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) throw CliError(file, "is not a JSON document");
  if (doc.value("command", "") != "render") throw CliError(file, "is not the output of `shadowlab render --json`");
  ShardDoc d;
  const scenes::JsonIn root(doc, "", file);
  const scenes::JsonIn batch = root.member("batch");
  if (!batch.value().is_null()) batch.string();
  d.batch = batch.value();
  d.jobs_total = root.member("jobs_total").integer(0, kMost);
  const scenes::JsonIn job_scenes = root.member("job_scenes");
  const std::vector<scenes::JsonIn> scenes_of_jobs = job_scenes.items();
  if (scenes_of_jobs.size() != d.jobs_total)
    job_scenes.fail(std::to_string(scenes_of_jobs.size()) + " scenes for " + std::to_string(d.jobs_total) + " jobs");
  for (const scenes::JsonIn& scene : scenes_of_jobs) scene.string();
  d.job_scenes = job_scenes.value();
  const scenes::JsonIn shard = root.member("shard");
  d.count = shard.member("count").integer(1, kMost);
  d.index = shard.member("index").integer(0, d.count - 1);
  for (const scenes::JsonIn& job : root.member("jobs").items()) {
    d.job_index.push_back(job.member("index").integer(0, kMost));
    d.frames += job.member("frames").items().size();
    d.jobs.push_back(job.value());
  }
  d.wall_ms = root.member("summary").member("wall_ms").number();
  return d;
}

int run_merge(const MergeArgs& a) {
  if (!a.out.empty()) check_output_dir(a.out, "--out");
  std::vector<ShardDoc> docs;
  for (const std::string& f : a.shards) docs.push_back(read_doc(f));
  const ShardDoc& first = docs.front();
  const size_t count = first.count;
  if (count != docs.size())
    throw CliError(a.shards[0], "belongs to a run of " + std::to_string(count) + " shards, " +
                                    std::to_string(docs.size()) + " given");
  std::vector<bool> seen(count, false);
  std::vector<std::pair<uint32_t, const nlohmann::json*>> jobs;  // batch index, job
  size_t frames = 0;
  double wall_ms = 0;
  for (size_t i = 0; i < docs.size(); ++i) {
    const ShardDoc& d = docs[i];
    if (d.batch != first.batch || d.job_scenes != first.job_scenes || d.count != count)
      throw CliError(a.shards[i], "belongs to another run than " + a.shards[0] +
                                      " (batch, its jobs' scenes or shard count differ)");
    if (seen[d.index]) throw CliError(a.shards[i], "repeats shard " + std::to_string(d.index));
    seen[d.index] = true;
    for (size_t k = 0; k < d.jobs.size(); ++k) {
      // Shard I runs the jobs K with K mod N = I: a job outside its shard's share is another run's.
      if (d.job_index[k] >= first.jobs_total || d.job_index[k] % count != d.index)
        throw CliError(a.shards[i], "jobs[" + std::to_string(k) + "].index: " + std::to_string(d.job_index[k]) +
                                        " is not a job of shard " + std::to_string(d.index) + "/" +
                                        std::to_string(count) + " of " + std::to_string(first.jobs_total));
      jobs.emplace_back(d.job_index[k], &d.jobs[k]);
    }
    frames += d.frames;
    wall_ms += d.wall_ms;
  }
  std::stable_sort(jobs.begin(), jobs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (size_t k = 1; k < jobs.size(); ++k)
    if (jobs[k].first == jobs[k - 1].first)
      throw CliError(a.shards[0], "job " + std::to_string(jobs[k].first) + " is in the shards twice");
  if (jobs.size() != first.jobs_total)
    throw CliError(a.shards[0], "the shards hold " + std::to_string(jobs.size()) + " jobs of " +
                                    std::to_string(first.jobs_total));
  nlohmann::json merged_jobs = nlohmann::json::array();
  for (const auto& job : jobs) merged_jobs.push_back(*job.second);
  nlohmann::json merged = {{"command", "render"},
                           {"batch", first.batch},
                           {"jobs_total", first.jobs_total},
                           {"job_scenes", first.job_scenes},
                           {"shard", {{"index", 0}, {"count", 1}}},
                           {"merged_from", count},
                           {"jobs", merged_jobs},
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
