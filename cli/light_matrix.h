// Light matrix files (CONVENTIONS): `{"view": [16], "proj": [16]}` or `{"view_proj": [16]}`, each matrix as its
// 16 floats in glm::value_ptr order, so `shadowlab shadowmap` uses exactly what an engine rendered with.
#pragma once
#include <filesystem>

#include <glm/mat4x4.hpp>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

struct LightMatrices {
  glm::mat4 view{1.0f};       // identity when the file gives only view_proj
  glm::mat4 view_proj{1.0f};  // proj · view, or the file's view_proj
};

// Reads and checks a light matrix file. Throws CliError `FILE: KEY: what is wrong` for a missing file,
// malformed JSON, unknown or missing keys, and arrays that are not 16 finite numbers.
LightMatrices read_light_matrices(const std::filesystem::path& path);

SHADOWLAB_ISA_END
}  // namespace cli
