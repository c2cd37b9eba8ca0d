// shadowlab's command line for one instruction set (cli/main.cpp picks which): builds the parser from the
// per-command files, runs the chosen command, and is the one place where errors become
// `shadowlab: error: WHERE: what is wrong` and exit code 2.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.h"
#include "cli/json_output.h"
#include "raster/renderer.h"
#include "raster/target.h"
#include "scenes/io/io_error.h"
#include "scenes/reference/occlusion_scene.h"
#include "scenes/scene_error.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr int kExitBadInput = 2;

// Prints exactly one line: newlines inside a library's message are folded into spaces.
int report(const std::string& message) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::fprintf(stderr, "shadowlab: error: %s\n", line.c_str());
  return kExitBadInput;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"shadowlab: a CPU rasterizer that reproduces the GL pipeline for shadow-mapping research.",
               "shadowlab"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");
  app.set_version_flag("--version", version_line(), "Print the version, git revision and SIMD path, and exit");
  app.footer("Environment: SHADOWLAB_ISA=avx512|avx2|scalar|auto chooses the instruction set the pipeline runs on "
             "(default auto: the widest the CPU has; every set writes the same bytes).");
  std::vector<Command> commands = {add_render_command(app), add_shadowmap_command(app),
                                   add_inspect_command(app), add_diff_command(app),
                                   add_eval_command(app),    add_eval_merge_command(app),
                                   add_list_command(app),    add_render_merge_command(app),
                                   add_check_command(app),   add_scene_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    return report(e.what());
  }

  try {
    for (const Command& c : commands)
      if (c.app->parsed()) return c.run();
    return report("no command given (run shadowlab --help)");
  } catch (const CliError& e) {
    return report(e.what());
  } catch (const scenes::SceneError& e) {
    return report(e.what());
  } catch (const scenes::io::IoError& e) {
    return report(e.what());
  } catch (const reference::ReferenceError& e) {
    return report(e.what());
  } catch (const raster::TargetSizeError& e) {
    return report(std::string("target size: ") + e.what());
  } catch (const raster::DrawError& e) {
    return report(std::string("draw: ") + e.what());
  } catch (const std::invalid_argument& e) {  // frame::render_frame: the message names the option
    return report(e.what());
  } catch (const std::bad_alloc&) {
    return report("out of memory");
  } catch (const std::exception& e) {
    return report(std::string("internal error: ") + e.what());
  }
}

SHADOWLAB_ISA_END
}  // namespace cli
