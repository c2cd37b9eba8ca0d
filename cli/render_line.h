// One render job run from inside another command (`check`): the same options, checks, frames and outputs as
// `shadowlab render`, given as a command line's words.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// Renders `args` (the words after `shadowlab render`: one scene and options) and returns the job as `render
// --json` describes it (scene, name, frames with their outputs). Errors are CliErrors on `where`.
nlohmann::json render_line(const std::vector<std::string>& args, const std::string& where);
// Every check render_line makes before it renders (options, names, the scene's existence, output folders), so
// a command running several lines can fail on a bad one before the first renders.
void check_render_line(const std::vector<std::string>& args, const std::string& where);

SHADOWLAB_ISA_END
}  // namespace cli
