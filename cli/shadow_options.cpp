// The shadow-setting options of render and eval (see shadow_options.h).
#include "cli/shadow_options.h"

#include <span>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "scenes/shadow_settings.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace tech = shading::tech;

// Every technique parameter once (the filter parameters and each built technique's own), in table order.
std::vector<const tech::ParamSpec*> all_params() {
  std::vector<const tech::ParamSpec*> out;
  auto add = [&](std::span<const tech::ParamSpec> list) {
    for (const auto& p : list) {
      bool seen = false;
      for (const auto* q : out) seen |= q->key == p.key;
      if (!seen) out.push_back(&p);
    }
  };
  add(tech::kFilterParams);
  for (const tech::TechniqueInfo& t : tech::kTechniques)
    if (t.built) add(t.params);
  return out;
}

// The value options beside the parameters: option, frame field, help, and the member they fill.
struct ValueOption {
  const char* option;
  const char* field;
  const char* help;
  std::optional<float> ShadowOverrides::*member;
};
constexpr ValueOption kValues[] = {
    {"--poisson-spread", "poisson_spread", "Poisson disc radius in map texture coordinates (1/700)",
     &ShadowOverrides::poisson_spread},
    {"--bias-constant", "bias.constant", "constant bias: window depth subtracted (0.005)", &ShadowOverrides::bias_constant},
    {"--bias-slope", "bias.slope", "slope bias: scale of tan(acos(N.L)) (0.005)", &ShadowOverrides::bias_slope},
    {"--bias-slope-max", "bias.slope_max", "slope bias: upper clamp (0.01)", &ShadowOverrides::bias_slope_max},
    {"--offset-factor", "bias.offset_factor", "offset bias: glPolygonOffset factor (1.1)", &ShadowOverrides::offset_factor},
    {"--offset-units", "bias.offset_units", "offset bias: glPolygonOffset units (4)", &ShadowOverrides::offset_units},
    {"--normal-offset", "bias.normal_offset", "normal bias: receiver moved along its normal, metres (0.02)",
     &ShadowOverrides::normal_offset},
};

}  // namespace

void add_shadow_options(CLI::App& app, ShadowOverrides& target) {
  ShadowOverrides* t = &target;
  app.add_option("--poisson-taps", t->poisson_taps, "Poisson filters: 4 or 16 taps");
  for (const ValueOption& v : kValues) {
    std::optional<float>* member = &(t->*v.member);
    app.add_option_function<float>(v.option, [member](const float& x) { *member = x; }, v.help);
  }
  app.add_option("--depth-format", t->depth_format, "Depth format of every light's maps (see list)");
  // The technique parameters (vocabulary.h): one option each, flags with a --no- form.
  for (const tech::ParamSpec* p : all_params()) {
    const std::string key(p->key), option(p->option),
        help = std::string(p->help) + " (default " + std::string(p->fallback) + ")";
    switch (p->kind) {
      case tech::ParamKind::flag:
        app.add_flag_callback(option, [t, key] { t->params[key] = true; }, help);
        app.add_flag_callback("--no-" + option.substr(2), [t, key] { t->params[key] = false; }, "");
        break;
      case tech::ParamKind::number:
      case tech::ParamKind::integer:
        app.add_option_function<double>(option, [t, key](const double& x) { t->params[key] = x; }, help);
        break;
      case tech::ParamKind::choice:
      case tech::ParamKind::text:
        app.add_option_function<std::string>(option, [t, key](const std::string& x) { t->params[key] = x; }, help);
        break;
    }
  }
}

void check_shadow_overrides(const ShadowOverrides& o) {
  if (!o.depth_format.empty() && !scenes::parse_depth_format(o.depth_format))
    throw CliError("--depth-format", "unknown depth format '" + o.depth_format +
                                         "' (known: " + scenes::join_names(scenes::depth_format_names()) + ")");
  if (o.poisson_taps && *o.poisson_taps != 4 && *o.poisson_taps != 16)
    throw CliError("--poisson-taps", std::to_string(*o.poisson_taps) + " is not 4 or 16");
  for (const tech::ParamSpec* p : all_params())
    if (const auto it = o.params.find(std::string(p->key)); it != o.params.end())
      if (auto why = tech::value_problem(*p, it->second)) throw CliError(std::string(p->option), *why);
}

void apply_shadow_overrides(const ShadowOverrides& o, frame::FrameConfig& config) {
  if (!o.depth_format.empty()) config.depth_format = scenes::parse_depth_format(o.depth_format);
  if (o.poisson_taps) config.poisson_taps = *o.poisson_taps;
  config.poisson_spread = o.poisson_spread;
  config.bias_constant = o.bias_constant;
  config.bias_slope = o.bias_slope;
  config.bias_slope_max = o.bias_slope_max;
  config.offset_factor = o.offset_factor;
  config.offset_units = o.offset_units;
  config.normal_offset = o.normal_offset;
  config.params = o.params;
}

nlohmann::json shadow_overrides_json(const ShadowOverrides& o) {
  nlohmann::json j = nlohmann::json::object();
  if (!o.depth_format.empty()) j["depth-format"] = o.depth_format;
  if (o.poisson_taps) j["poisson-taps"] = *o.poisson_taps;
  for (const ValueOption& v : kValues)
    if (const std::optional<float>& x = o.*v.member) j[std::string(v.option).substr(2)] = *x;
  for (const tech::ParamSpec* p : all_params())
    if (const auto it = o.params.find(std::string(p->key)); it != o.params.end())
      std::visit([&](const auto& x) { j[std::string(p->option).substr(2)] = x; }, it->second);
  return j;
}

std::optional<std::string> shadow_option_for_field(const std::string& field) {
  if (field == "poisson_taps") return "--poisson-taps";
  for (const ValueOption& v : kValues)
    if (field == v.field) return std::string(v.option);
  if (field.rfind("params.", 0) == 0)
    for (const tech::ParamSpec* p : all_params())
      if (field == "params." + std::string(p->key)) return std::string(p->option);
  return std::nullopt;
}

SHADOWLAB_ISA_END
}  // namespace cli
