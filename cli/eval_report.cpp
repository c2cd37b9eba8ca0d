// eval.json, eval.csv and --shard (see eval_report.h).
#include "cli/eval_report.h"

#include <fstream>

#include "cli/cli_common.h"
#include "cli/eval_html.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

const char* const kColumns[] = {"index", "combination", "technique", "filter", "bias", "map_size", "light",
                                "light_name", "used_technique", "used_filter", "used_bias", "used_map_size",
                                "used_depth_format", "scored_pixels", "unreached_pixels", "false_shadowed_pct", "false_shadowed_near_pct",
                                "false_shadowed_elsewhere_pct", "false_lit_pct", "false_lit_near_pct",
                                "false_lit_elsewhere_pct", "false_shadowed_pixels", "false_lit_pixels",
                                "mean_abs_error", "largest_false_lit_group", "longest_false_lit_run", "map_pass_ms",
                                "camera_pass_ms", "score_ms", "shimmer_camera_pct", "shimmer_light_pct",
                                "aliasing_max", "aliasing_p95", "aliasing_mean"};

void stage_text(scenes::io::WriteBatch& batch, const std::filesystem::path& path, const std::string& text) {
  batch.stage(path, [&](const std::filesystem::path& tmp) { scenes::io::write_bytes(tmp, text.data(), text.size()); });
}

}  // namespace

std::span<const char* const> eval_columns() { return kColumns; }

Shard parse_shard(const std::string& text, const std::string& option) {
  if (text.empty()) return {};
  const size_t slash = text.find('/');
  auto number = [&](const std::string& part) -> long long {
    size_t used = 0;
    long long v = -1;
    try {
      v = std::stoll(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (part.empty() || used != part.size() || part[0] == '-' || part[0] == '+')
      throw CliError(option, "expected I/N with whole numbers, got '" + text + "'");
    return v;
  };
  if (slash == std::string::npos) throw CliError(option, "expected I/N, got '" + text + "'");
  const long long i = number(text.substr(0, slash)), n = number(text.substr(slash + 1));
  if (n < 1 || n > 100000) throw CliError(option, "the shard count " + std::to_string(n) + " is outside 1..100000");
  if (i >= n) throw CliError(option, "the shard index " + std::to_string(i) + " is not below the count " + std::to_string(n));
  return {size_t(i), size_t(n)};
}

std::string eval_csv(const nlohmann::json& results) {
  std::string out;
  for (const char* c : kColumns) out += std::string(out.empty() ? "" : ",") + c;
  out += "\n";
  for (const auto& r : results) {
    bool first = true;
    for (const char* c : kColumns) {
      const auto& v = r.at(c);
      std::string cell = v.is_string() ? v.get<std::string>() : v.is_null() ? std::string() : v.dump();
      if (cell.find_first_of(",\"\n") != std::string::npos) {  // RFC 4180 quoting
        std::string q = "\"";
        for (char ch : cell) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        cell = q + "\"";
      }
      out += (first ? "" : ",") + cell;
      first = false;
    }
    out += "\n";
  }
  return out;
}

void write_eval_report(const std::filesystem::path& dir, const nlohmann::json& report, const ContactSheets& sheets) {
  const std::string html = eval_html(report, sheets);  // before anything is staged: a missing sheet writes nothing
  scenes::io::WriteBatch batch;
  for (const auto& sheet : sheets) {
    const auto& png = sheet.second;  // a plain reference: clang 14 cannot capture a structured binding
    batch.stage(dir / (sheet.first + ".png"),
                [&](const std::filesystem::path& tmp) { scenes::io::write_bytes(tmp, png.data(), png.size()); });
  }
  stage_text(batch, dir / "eval.json", report.dump(2) + "\n");
  stage_text(batch, dir / "eval.csv", eval_csv(report.at("results")));
  stage_text(batch, dir / "eval.html", html);
  batch.commit();
}

SHADOWLAB_ISA_END
}  // namespace cli
