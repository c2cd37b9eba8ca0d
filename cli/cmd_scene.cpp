// `shadowlab scene export NAME`: a built-in scene written as a JSON scene (docs/scene-format.md), so a user starts
// a scene file from one; the file renders exactly as the built-in does. Written to stdout, or with --out to a file
// through a temporary name (a failed run leaves no file).
#include <cstdio>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.h"
#include "scenes/builtin_scenes.h"
#include "scenes/io/atomic_write.h"
#include "scenes/scene_json.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct ExportArgs {
  std::string name, out;
  double time = 0.0;
};

int run_export(const ExportArgs& a) {
  if (!scenes::is_builtin_scene(a.name)) {
    std::string known;
    for (const scenes::BuiltinInfo& b : scenes::list_builtin_scenes())
      known += (known.empty() ? "" : ", ") + std::string(b.name);
    throw CliError(a.name, "not a built-in scene (known: " + known + ")");
  }
  scenes::BuiltinParams params;
  params.time = a.time;
  const std::string text = scenes::scene_json_text(scenes::builtin_scene_desc(a.name, params));
  if (a.out.empty()) {
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
      throw CliError("stdout", "cannot write the scene");
    return 0;
  }
  scenes::io::WriteBatch batch;
  batch.stage(a.out, [&](const std::filesystem::path& tmp) { scenes::io::write_bytes(tmp, text.data(), text.size()); });
  batch.commit();
  return 0;
}

}  // namespace

Command add_scene_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand("scene", "Scene files: export a built-in scene as JSON");
  app->require_subcommand(1);
  auto args = std::make_shared<ExportArgs>();
  CLI::App* ex = app->add_subcommand(
      "export", "Write a built-in scene as a JSON scene (docs/scene-format.md) that renders the same frames");
  ex->add_option("name", args->name, "A built-in scene (see list)")->required();
  ex->add_option("--time", args->time, "Animated scenes (projective): the time in seconds (default 0)");
  ex->add_option("--out", args->out, "Write to this file instead of stdout");
  return {app, [args] { return run_export(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
