// Reading light matrix JSON files strictly: every problem names the file and the key (see light_matrix.h).
#include "cli/light_matrix.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

glm::mat4 matrix_of(const nlohmann::json& value, const std::string& file, const std::string& key) {
  if (!value.is_array()) throw CliError(file, key + ": expected an array of 16 numbers");
  if (value.size() != 16)
    throw CliError(file, key + ": expected 16 numbers, got " + std::to_string(value.size()));
  glm::mat4 m(1.0f);
  float* out = glm::value_ptr(m);
  for (size_t i = 0; i < 16; ++i) {
    const nlohmann::json& v = value[i];
    if (!v.is_number()) throw CliError(file, key + "[" + std::to_string(i) + "]: expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > double(std::numeric_limits<float>::max()))
      throw CliError(file, key + "[" + std::to_string(i) + "]: expected a finite number that fits in a float");
    out[i] = float(d);
  }
  // A singular matrix maps the scene onto a plane, a line or a point: no depth map can come of it.
  if (!(std::fabs(glm::determinant(glm::dmat4(m))) > 0.0))
    throw CliError(file, key + ": a singular matrix (determinant 0): it maps the scene onto less than a volume");
  return m;
}

}  // namespace

LightMatrices read_light_matrices(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CliError(file, std::filesystem::exists(path) ? "cannot open file" : "no such file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number like 1e999
    std::string what = e.what();
    // nlohmann prefixes "[json.exception.parse_error.101] " (or out_of_range.406); the rest reads well alone.
    if (const size_t close = what.find("] "); what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
      what = what.substr(close + 2);
    throw CliError(file, "malformed JSON: " + what);
  }
  if (!doc.is_object()) throw CliError(file, "expected an object with \"view\" and \"proj\", or \"view_proj\"");
  for (const auto& [key, value] : doc.items())
    if (key != "view" && key != "proj" && key != "view_proj") throw CliError(file, key + ": unknown key");

  LightMatrices m;
  if (doc.contains("view_proj")) {
    if (doc.contains("view") || doc.contains("proj"))
      throw CliError(file, "view_proj: cannot be combined with view and proj");
    m.view_proj = matrix_of(doc["view_proj"], file, "view_proj");
    return m;
  }
  if (!doc.contains("view")) throw CliError(file, "view: missing (give \"view\" and \"proj\", or \"view_proj\")");
  if (!doc.contains("proj")) throw CliError(file, "proj: missing (give \"view\" and \"proj\", or \"view_proj\")");
  m.view = matrix_of(doc["view"], file, "view");
  m.view_proj = matrix_of(doc["proj"], file, "proj") * m.view;
  return m;
}

SHADOWLAB_ISA_END
}  // namespace cli
