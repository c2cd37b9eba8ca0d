// --exposure, --tonemap and --background for render: how a frame is shown (scenes/look.h), overriding the scene's
// own. Parsed before the scene is loaded, so a bad value fails before any work.
#pragma once
#include <optional>
#include <string>

#include "scenes/look.h"
#include "raster/simd/isa.h"

namespace CLI {
class App;
}  // namespace CLI

namespace cli {
SHADOWLAB_ISA_BEGIN

struct LookArgs {
  std::string exposure, tonemap, background;  // as given; empty: the scene's
};

void add_look_options(CLI::App& app, LookArgs& args);

struct LookOverrides {
  std::optional<scenes::Exposure> exposure;
  std::optional<shading::ToneMap> tone_map;
  std::optional<scenes::Background> background;
};

// The overrides the options give. CliError on the option for a bad value: --exposure takes `auto` or an EV100 in
// -64..64; --tonemap a name; --background a name, R,G,B or R,G,B,R,G,B (top, then bottom), linear in [0, 1].
LookOverrides parse_look(const LookArgs& args);

SHADOWLAB_ISA_END
}  // namespace cli
