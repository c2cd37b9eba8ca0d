// The look options of render (see look_options.h).
#include "cli/look_options.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

// Comma-separated numbers; nothing when a part is not a number.
std::optional<std::vector<float>> numbers(const std::string& text) {
  std::vector<float> v;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, end - start);
    size_t used = 0;
    float x = 0.0f;
    try {
      x = std::stof(part, &used);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != part.size() || !std::isfinite(x)) return std::nullopt;
    v.push_back(x);
    start = end + 1;
  }
  return v;
}

std::string background_names() {
  std::string known;
  for (const scenes::NamedBackground& b : scenes::kBackgrounds) known += (known.empty() ? "" : ", ") + std::string(b.name);
  return known;
}

}  // namespace

void add_look_options(CLI::App& app, LookArgs& args) {
  app.add_option("--exposure", args.exposure,
                 "Camera exposure: EV100 (e.g. 15 for sunlight, 8 for a lit room) or auto, metered from the frame "
                 "(default: the scene's, else auto)");
  app.add_option("--tonemap", args.tonemap,
                 "Tone map: neutral (Khronos PBR Neutral), aces (ACES fitted) or clamp (default: the scene's, else "
                 "neutral)");
  app.add_option("--background", args.background,
                 "Background: " + background_names() +
                     ", R,G,B or R,G,B,R,G,B (top, bottom; linear 0..1) (default: the scene's, else sky)");
}

LookOverrides parse_look(const LookArgs& args) {
  LookOverrides o;
  if (args.exposure == "auto") {
    o.exposure = scenes::Exposure{};
  } else if (!args.exposure.empty()) {
    const auto v = numbers(args.exposure);
    if (!v || v->size() != 1 || !((*v)[0] >= -64.0f && (*v)[0] <= 64.0f))
      throw CliError("--exposure", "expected auto or an EV100 between -64 and 64, got '" + args.exposure + "'");
    o.exposure = scenes::Exposure{(*v)[0]};
  }
  if (!args.tonemap.empty()) {
    o.tone_map = shading::parse_tone_map(args.tonemap);
    if (!o.tone_map) {
      std::string known;
      for (const shading::ToneMapName& n : shading::kToneMapNames) known += (known.empty() ? "" : ", ") + std::string(n.name);
      throw CliError("--tonemap", "unknown tone map '" + args.tonemap + "' (known: " + known + ")");
    }
  }
  if (!args.background.empty()) {
    o.background = scenes::named_background(args.background);
    if (!o.background) {
      const auto v = numbers(args.background);
      bool ok = v && (v->size() == 3 || v->size() == 6);
      for (size_t i = 0; ok && i < v->size(); ++i) ok = (*v)[i] >= 0.0f && (*v)[i] <= 1.0f;
      if (!ok)
        throw CliError("--background", "expected " + background_names() +
                                           ", R,G,B or R,G,B,R,G,B with numbers in [0, 1], got '" + args.background + "'");
      const glm::vec3 top((*v)[0], (*v)[1], (*v)[2]);
      o.background = scenes::Background{top, v->size() == 6 ? glm::vec3((*v)[3], (*v)[4], (*v)[5]) : top};
    }
  }
  return o;
}

SHADOWLAB_ISA_END
}  // namespace cli
