// Light choice for render and eval (see light_choice.h).
#include "cli/light_choice.h"

#include <cctype>

#include "cli/cli_common.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

std::optional<size_t> choose_light(scenes::Scene& scene, const std::string& spec) {
  if (spec.empty()) return std::nullopt;
  std::string names;
  for (size_t i = 0; i < scene.lights.size(); ++i)
    names += (names.empty() ? "" : ", ") + std::to_string(i) +
             (scene.lights[i].name.empty() ? "" : " '" + scene.lights[i].name + "'");
  const std::string known = scene.lights.empty() ? "the scene has no lights" : "lights: " + names;
  std::optional<size_t> index;
  for (size_t i = 0; i < scene.lights.size() && !index; ++i)
    if (scene.lights[i].name == spec) index = i;  // a name first: a light may be named "1"
  bool digits = spec.size() < 10;
  for (char ch : spec) digits &= std::isdigit(static_cast<unsigned char>(ch)) != 0;
  if (!index && digits) {
    const size_t i = std::stoul(spec);
    if (i >= scene.lights.size()) throw CliError("--light", "light " + spec + " does not exist (" + known + ")");
    index = i;
  }
  if (!index) throw CliError("--light", "no light named '" + spec + "' (" + known + "; or an index)");
  scenes::Light kept = scene.lights[*index];
  scene.lights.assign(1, std::move(kept));
  return index;
}

std::string light_field(const std::string& field, std::optional<size_t> chosen) {
  const std::string first = "lights[0]";
  if (!chosen || field.rfind(first, 0) != 0) return field;
  return "lights[" + std::to_string(*chosen) + "]" + field.substr(first.size());
}

SHADOWLAB_ISA_END
}  // namespace cli
