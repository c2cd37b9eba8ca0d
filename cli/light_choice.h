// --light for render and eval: one light of the scene, picked by name or index, rendered alone (the others are
// taken out of the scene before the frame is set up, so no map is built for them).
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// Keeps only the light `spec` names (its name, or its index in the scene's lights) and returns that index;
// nullopt and no change for an empty spec. CliError on --light for a name or index the scene does not have,
// listing the lights it has.
std::optional<size_t> choose_light(scenes::Scene& scene, const std::string& spec);

// A frame error's field for the one light left by choose_light (`lights[0]...`) named by the light's place in
// the scene as loaded (`lights[K]...`), so a message points at the light in the file; any other field unchanged.
std::string light_field(const std::string& field, std::optional<size_t> chosen);

SHADOWLAB_ISA_END
}  // namespace cli
