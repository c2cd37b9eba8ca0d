// `shadowlab list`: the built-in scenes, shadow techniques (with the light types each serves, whether it is
// built, its map defaults and its parameters), filters, bias modes and depth formats, from the vocabulary's
// tables: as aligned text, or with --json as one document (docs/cli/list.schema.json).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/json_output.h"
#include "scenes/builtin_scenes.h"
#include "scenes/shadow_settings.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

namespace tech = shading::tech;

constexpr const char* kKindNames[] = {"flag", "number", "integer", "choice", "text"};

nlohmann::json param_json(const tech::ParamSpec& p) {
  nlohmann::json j = {{"key", p.key},   {"option", p.option}, {"kind", kKindNames[size_t(p.kind)]},
                      {"default", p.fallback}, {"help", p.help}};
  if (p.kind == tech::ParamKind::number || p.kind == tech::ParamKind::integer) j["range"] = {p.lo, p.hi};
  if (p.kind == tech::ParamKind::choice) {
    nlohmann::json choices = nlohmann::json::array();
    for (std::string_view c : p.choices)
      if (!c.empty()) choices.push_back(c);
    j["choices"] = choices;
  }
  return j;
}

nlohmann::json table_json(std::span<const scenes::NamedEntry> table) {
  nlohmann::json out = nlohmann::json::array();
  for (const scenes::NamedEntry& e : table) out.push_back({{"name", e.name}, {"description", e.description}});
  return out;
}

nlohmann::json list_json() {
  nlohmann::json scenes_j = nlohmann::json::array();
  for (const scenes::BuiltinInfo& s : scenes::list_builtin_scenes())
    scenes_j.push_back({{"name", s.name}, {"description", s.description}, {"animated", s.animated}});
  nlohmann::json techniques = nlohmann::json::array();
  for (const tech::TechniqueInfo& t : tech::kTechniques) {
    nlohmann::json lights = nlohmann::json::array(), params = nlohmann::json::array();
    for (size_t i = 0; i < std::size(tech::kLightTypeNames); ++i)
      if (t.lights & (1u << i)) lights.push_back(tech::kLightTypeNames[i].name);
    for (const tech::ParamSpec& p : t.params) params.push_back(param_json(p));
    techniques.push_back({{"name", t.name},
                          {"description", t.description},
                          {"lights", lights},
                          {"built", t.built},
                          {"map_size", t.map_size},
                          {"depth_format", tech::to_string(t.depth_format)},
                          {"encoding", t.encoding},
                          {"reads_filter", t.reads_filter},
                          {"params", params}});
  }
  nlohmann::json filter_params = nlohmann::json::array();
  for (const tech::ParamSpec& p : tech::kFilterParams) filter_params.push_back(param_json(p));
  return {{"command", "list"},
          {"scenes", scenes_j},
          {"techniques", techniques},
          {"filters", table_json(scenes::filter_names())},
          {"biases", table_json(scenes::bias_mode_names())},
          {"depth_formats", table_json(scenes::depth_format_names())},
          {"light_types", table_json(tech::kLightTypeNames)},
          {"filter_params", filter_params}};
}

void print_line(std::string_view kind, std::string_view name, std::string_view description) {
  std::printf("%-10.*s %-16.*s %.*s\n", int(kind.size()), kind.data(), int(name.size()), name.data(),
              int(description.size()), description.data());
}

void print_table(std::string_view kind, std::span<const scenes::NamedEntry> table) {
  for (const scenes::NamedEntry& e : table) print_line(kind, e.name, e.description);
}

int run_list(bool json) {
  if (json) {
    print_json(list_json());
    return 0;
  }
  for (const scenes::BuiltinInfo& s : scenes::list_builtin_scenes()) print_line("scene", s.name, s.description);
  for (const tech::TechniqueInfo& t : tech::kTechniques) {
    // The map a light of this technique gets when the scene gives none (`none` builds no map; the irregular
    // z-buffer, which stores no depths, takes map_size as its grid's largest side).
    const std::string size = std::to_string(t.map_size) + "²";
    const std::string map = t.map_size == 0      ? std::string()
                            : t.encoding.empty() ? "; grid of at most " + size + " cells"
                                                 : "; map " + size + " " + std::string(tech::to_string(t.depth_format));
    const std::string line = std::string(t.description) + " [lights: " + tech::light_names(t.lights) + map +
                             (t.built ? "]" : "; not built yet]");
    print_line("technique", t.name, line);
  }
  print_table("filter", scenes::filter_names());
  print_table("bias", scenes::bias_mode_names());
  print_table("format", scenes::depth_format_names());
  // One line per parameter, naming the techniques that take it (a parameter several share is listed once; its
  // default, where they differ, per technique).
  std::vector<std::string_view> keys;
  for (const tech::TechniqueInfo& t : tech::kTechniques)
    for (const tech::ParamSpec& p : t.params)
      if (std::find(keys.begin(), keys.end(), p.key) == keys.end()) keys.push_back(p.key);
  for (std::string_view key : keys) {
    const tech::ParamSpec* first = nullptr;
    std::string names, defaults;
    bool same = true;
    for (const tech::TechniqueInfo& t : tech::kTechniques)
      for (const tech::ParamSpec& p : t.params)
        if (p.key == key) {
          if (!first) first = &p;
          same &= p.fallback == first->fallback;
          names += (names.empty() ? "" : ", ") + std::string(t.name);
          defaults += (defaults.empty() ? "" : ", ") + std::string(p.fallback) + " (" + std::string(t.name) + ")";
        }
    print_line("param", key,
               std::string(first->help) + " (" + std::string(first->option) + ", default " +
                   (same ? std::string(first->fallback) : defaults) + "; " + names + ")");
  }
  for (const tech::ParamSpec& p : tech::kFilterParams)
    print_line("param", p.key,
               "every technique with a map: " + std::string(p.help) + " (" + std::string(p.option) + ", default " +
                   std::string(p.fallback) + ")");
  return 0;
}

}  // namespace

Command add_list_command(CLI::App& parent) {
  auto json = std::make_shared<bool>(false);
  CLI::App* app = parent.add_subcommand("list", "List built-in scenes, shadow techniques, filters and bias modes");
  app->add_flag("--json", *json, "Print JSON (docs/cli/list.schema.json) instead of text");
  return {app, [json] { return run_list(*json); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
