// The eval report as one self-contained HTML page (DIR/eval.html): the reference and scoring rules, the results
// table (click a column header to sort by it), and each combination's contact sheet (frame | error map) embedded
// as a data: URI, so the page can be mailed or archived alone. Shared by `eval` and `eval-merge`.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// Each combination's contact sheet as PNG bytes, by combination label.
using ContactSheets = std::map<std::string, std::vector<unsigned char>>;

// The page for `report` (eval.json's content), embedding `sheets`; a combination without a sheet throws
// CliError naming it.
std::string eval_html(const nlohmann::json& report, const ContactSheets& sheets);

SHADOWLAB_ISA_END
}  // namespace cli
