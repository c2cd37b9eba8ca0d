// The JSON record of one rendered frame, as `render --json` prints it per frame (docs/cli/render.schema.json,
// frames[]): times, draw counts, size, the pixels' hash, the maps, the aliasing figures and each technique's own
// statistics. The caller fills "outputs" once the files are written.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "raster/target.h"
#include "scenes/frame/frame.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// 64-bit FNV-1a of a frame's pixels (the linear RGBA8 target the PNG is encoded from), as 16 hex digits: equal
// hashes, equal frames.
std::string pixel_hash(const raster::ColorTarget& c);

// Frame `number` (1 for the first) of a job, rendered with `config` in `total_ms`.
nlohmann::json frame_json(int number, double total_ms, const frame::Frame& f, const frame::FrameConfig& config);

SHADOWLAB_ISA_END
}  // namespace cli
