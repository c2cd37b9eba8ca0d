// eval.html (see eval_html.h): a table, a few lines of JavaScript to sort it, and base64-embedded images.
#include "cli/eval_html.h"

#include <fstream>
#include <set>
#include <sstream>

#include "cli/cli_common.h"
#include "cli/eval_report.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16 | unsigned(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16;
    out += {k[v >> 18], k[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16 | unsigned(uint8_t(bytes[i + 1])) << 8;
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
  }
  return out;
}

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return escape(v.get<std::string>());
  if (v.is_number_float()) {
    std::ostringstream s;
    s.precision(4);
    s << v.get<double>();
    return s.str();
  }
  return escape(v.dump());
}

// Sorts by the clicked column: numerically where both cells are numbers, else as text; a second click reverses.
const char* kSortScript = R"(<script>
document.querySelectorAll('th').forEach((th, col) => th.addEventListener('click', () => {
  const body = th.closest('table').tBodies[0];
  const dir = th.dataset.dir = th.dataset.dir === 'asc' ? 'desc' : 'asc';
  const key = r => r.cells[col].textContent;
  [...body.rows].sort((a, b) => {
    const x = key(a), y = key(b), nx = parseFloat(x), ny = parseFloat(y);
    const c = (!isNaN(nx) && !isNaN(ny)) ? nx - ny : x.localeCompare(y);
    return dir === 'asc' ? c : -c;
  }).forEach(r => body.appendChild(r));
}));
</script>)";

}  // namespace

std::string eval_html(const nlohmann::json& report, const ContactSheets& sheets) {
  const nlohmann::json& results = report.at("results");
  const nlohmann::json& ref = report.at("reference");
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>shadowlab eval: "
    << escape(report.at("scene").get<std::string>()) << "</title>\n<style>"
    << "body{font-family:sans-serif;margin:1em}table{border-collapse:collapse;font-size:12px}"
    << "th,td{border:1px solid #ccc;padding:2px 6px;text-align:right}th{cursor:pointer;background:#eee}"
    << "td:nth-child(-n+8){text-align:left}img{max-width:100%}figure{margin:1em 0}</style></head><body>\n";
  h << "<h1>" << escape(report.at("scene").get<std::string>()) << "</h1>\n<p>Frame "
    << report.at("frame").at("width") << "&times;" << report.at("frame").at("height") << ". Reference: "
    << ref.at("triangles") << " triangles, " << ref.at("rays") << " rays in " << cell(ref.at("rays_ms"))
    << " ms, &epsilon; = " << cell(ref.at("epsilon")) << ". A pixel is in shadow for a technique below "
    << cell(report.at("scoring").at("shadow_below")) << "; near = within "
    << report.at("scoring").at("near_radius_pixels")
    << " pixels of an exact shadow boundary or a crease. Error maps: false-shadowed red, false-lit blue.</p>\n";
  if (const auto& sweep = report.at("sweep"); sweep.contains("settings") && !sweep.at("settings").empty()) {
    h << "<p>Settings of every combination:";
    for (const auto& [option, value] : sweep.at("settings").items())
      h << " <code>--" << escape(option) << " " << escape(value.is_string() ? value.get<std::string>() : value.dump())
        << "</code>";
    h << "</p>\n";
  }
  h << "<table id=\"results\"><thead><tr>";
  const std::span<const char* const> columns = eval_columns();
  for (const std::string c : columns) h << "<th>" << escape(c) << "</th>";
  h << "</tr></thead><tbody>\n";
  for (const auto& row : results) {
    h << "<tr>";
    for (const std::string c : columns) h << "<td>" << (row.contains(c) ? cell(row.at(c)) : "") << "</td>";
    h << "</tr>\n";
  }
  h << "</tbody></table>\n";
  std::set<std::string> shown;
  for (const auto& row : results) {
    const std::string label = row.at("combination").get<std::string>();
    if (!shown.insert(label).second) continue;
    const auto sheet = sheets.find(label);
    if (sheet == sheets.end()) throw CliError(label + ".png", "no contact sheet for the HTML page");
    const std::string bytes(sheet->second.begin(), sheet->second.end());
    h << "<figure><figcaption>" << escape(label)
      << " (frame | error map | the first light's aliasing heat map where measured)</figcaption><img alt=\""
      << escape(label) << "\" src=\"data:image/png;base64," << base64(bytes) << "\"></figure>\n";
  }
  h << kSortScript << "\n</body></html>\n";
  return h.str();
}

SHADOWLAB_ISA_END
}  // namespace cli
