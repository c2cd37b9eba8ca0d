// The shadow-setting options render and eval share: the depth format, Poisson taps and spread, the bias values,
// and one option per technique parameter (from the vocabulary's ParamSpec lists). Each overrides every light's
// own setting where it is given; checked before the scene is loaded, so a bad value fails before any work.
#pragma once
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "scenes/frame/frame.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace CLI {
class App;
}  // namespace CLI

namespace cli {
SHADOWLAB_ISA_BEGIN

struct ShadowOverrides {
  std::string depth_format;         // --depth-format, as given; empty: each light's own
  std::optional<int> poisson_taps;  // --poisson-taps
  std::optional<float> poisson_spread, bias_constant, bias_slope, bias_slope_max, offset_factor, offset_units,
      normal_offset;
  // Technique parameters by key (vocabulary.h), set only when given.
  std::map<std::string, shading::tech::ParamValue> params;
};

// Adds the options to `app`, filling `target` (which must outlive the parse).
void add_shadow_options(CLI::App& app, ShadowOverrides& target);
// CliError on the option: an unknown depth format, a tap count other than 4 or 16, a parameter value out of its
// range or choices.
void check_shadow_overrides(const ShadowOverrides& o);
// The given overrides copied into `config` (the others left as they are).
void apply_shadow_overrides(const ShadowOverrides& o, frame::FrameConfig& config);
// The given overrides as a JSON object keyed by option name without its dashes, for reports.
nlohmann::json shadow_overrides_json(const ShadowOverrides& o);
// The option that sets a frame field named at the start of a FrameError (`bias.constant` -> --bias-constant,
// `params.esm_c` -> --esm-c), or nothing.
std::optional<std::string> shadow_option_for_field(const std::string& field);

SHADOWLAB_ISA_END
}  // namespace cli
