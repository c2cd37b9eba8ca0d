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

// The length of the valid UTF-8 sequence starting at s[i], or 0 (a stray or overlong byte, a truncated one).
size_t utf8_length(const std::string& s, size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  const size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 && b >= 0xC2 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E && b <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return 0;
  return n;
}

// Prints exactly one line: newlines inside a library's message are folded into spaces, and bytes a terminal
// would act on or that are no UTF-8 (a corrupt file's header quoted by a library) are written as \xNN.
int report(const std::string& message) {
  std::string line;
  for (size_t i = 0; i < message.size();) {
    const auto b = static_cast<unsigned char>(message[i]);
    const size_t n = utf8_length(message, i);
    if (b == '\n' || b == '\r' || b == '\t') {
      line += ' ';
    } else if (n == 0 || b < 0x20 || b == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(b));
      line += hex;
    } else {
      line.append(message, i, n);
      i += n;
      continue;
    }
    ++i;
  }
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
  // A first word that is no option and no command is named as such (CLI11 would only say that a command is
  // required).
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const Command& c : commands) {
      known |= c.app->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) return report(std::string(argv[1]) + ": unknown command (known: " + names + ")");
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help
  } catch (const CLI::ExtrasError& e) {
    // The first word nothing took, named with the command whose options it is not one of.
    for (const Command& c : commands)
      if (c.app->parsed() && !c.app->remaining().empty()) {
        const std::string word = c.app->remaining().front(), name = c.app->get_name();
        return report(word + ": " + (word.rfind("-", 0) == 0 ? "unknown option" : "unexpected argument") +
                      " of shadowlab " + name + " (see shadowlab " + name + " --help)");
      }
    return report(e.what());
  } catch (const CLI::ParseError& e) {
    const std::string what = e.what();  // CLI11's own messages: an option's start with it, others get the command
    for (const Command& c : commands)
      if (c.app->parsed() && what.rfind("-", 0) != 0) return report(c.app->get_name() + ": " + what);
    if (what.rfind("-", 0) == 0) return report(what);
    return report(std::string("shadowlab: ") + e.what());
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
