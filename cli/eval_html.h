// The eval report as one self-contained HTML page (DIR/eval.html): the reference and scoring rules, the results
// table (click a column header to sort by it), and each combination's contact sheet (frame | error map) embedded
// as a data: URI, so the page can be mailed or archived alone. Shared by `eval` and `eval-merge`.
#pragma once
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace cli {

// The page for `report` (eval.json's content); the contact sheets are read from DIR/<combination>.png.
std::string eval_html(const nlohmann::json& report, const std::filesystem::path& dir);

}  // namespace cli
