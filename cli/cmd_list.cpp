// `shadowlab list`: the built-in scenes, shadow techniques (with the light types each serves, whether it is
// built, and its parameters), filters, bias modes and depth formats, from the vocabulary's tables.
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

#include "cli/cli_common.h"
#include "scenes/builtin_scenes.h"
#include "scenes/shadow_settings.h"

namespace cli {
namespace {

void print_line(std::string_view kind, std::string_view name, std::string_view description) {
  std::printf("%-10.*s %-16.*s %.*s\n", int(kind.size()), kind.data(), int(name.size()), name.data(),
              int(description.size()), description.data());
}

void print_table(std::string_view kind, std::span<const scenes::NamedEntry> table) {
  for (const scenes::NamedEntry& e : table) print_line(kind, e.name, e.description);
}

}  // namespace

Command add_list_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand("list", "List built-in scenes, shadow techniques, filters and bias modes");
  return {app, [] {
            for (const scenes::BuiltinInfo& s : scenes::list_builtin_scenes())
              print_line("scene", s.name, s.description);
            for (const shading::tech::TechniqueInfo& t : shading::tech::kTechniques) {
              std::string line = std::string(t.description) + " [lights: " + shading::tech::light_names(t.lights) +
                                 (t.built ? "]" : "; not built yet]");

              print_line("technique", t.name, line);
            }
            print_table("filter", scenes::filter_names());
            print_table("bias", scenes::bias_mode_names());
            print_table("format", scenes::depth_format_names());
            for (const shading::tech::TechniqueInfo& t : shading::tech::kTechniques)
              for (const shading::tech::ParamSpec& p : t.params)
                print_line("param", p.key,
                           std::string(p.help) + " (" + std::string(p.option) +
                               ", default " + std::string(p.fallback) + ")");
            for (const shading::tech::ParamSpec& p : shading::tech::kFilterParams)
              print_line("param", p.key,
                         "every technique with a map: " + std::string(p.help) + " (" + std::string(p.option) +
                             ", default " + std::string(p.fallback) + ")");
            return 0;
          }};
}

}  // namespace cli
