// --camera for render: a scene camera by name or index, or an orbit around the shadow casters
// (orbit:AZ,EL[,DIST], framed like the default camera when DIST is left out).
#pragma once
#include <cstddef>
#include <string>

#include <glm/vec3.hpp>

#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// orbit:AZ,EL[,DIST] as (azimuth from +Z towards +X, elevation, distance; 0: framed). CliError on --camera.
glm::vec3 parse_orbit(const std::string& spec);

// The camera `spec` picks, as an index into scene.cameras (an orbit camera is appended); empty: camera 0.
// CliError on --camera for a name or index the scene does not have.
size_t choose_camera(scenes::Scene& scene, const std::string& spec);

SHADOWLAB_ISA_END
}  // namespace cli
