// The files of an eval report, shared by `shadowlab eval` and `shadowlab eval-merge`: eval.json (the whole report:
// scene, frame, reference, scoring rules, sweep, one result per combination and light), eval.csv (the results
// as a table, one row each, in a fixed column order) and eval.html. Also `--shard I/N`, how a sweep is split across runs.
#pragma once
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/eval_html.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// Combinations K with K mod count == index belong to the shard.
struct Shard {
  size_t index = 0, count = 1;
};

// "I/N" with 0 <= I < N; empty: the whole sweep. `option` names the option in errors.
Shard parse_shard(const std::string& text, const std::string& option);

// The columns of a result, in table order (the CSV's and the HTML page's).
std::span<const char* const> eval_columns();

// The CSV of a report's "results" (header line first, RFC 4180 quoting).
std::string eval_csv(const nlohmann::json& results);

// Writes DIR/<combination>.png for every contact sheet, DIR/eval.json, DIR/eval.csv and DIR/eval.html (which
// embeds the sheets) as one WriteBatch: all of them are staged through temporaries first and renamed into place
// together, so a full disk or a failed write leaves none of them (and no damaged older file).
void write_eval_report(const std::filesystem::path& dir, const nlohmann::json& report, const ContactSheets& sheets);

SHADOWLAB_ISA_END
}  // namespace cli
