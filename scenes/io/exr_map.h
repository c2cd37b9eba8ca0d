// Shadow maps as OpenEXR files, exactly as CONVENTIONS lays them out: one FLOAT channel `Z`, rows top first,
// the light's matrices as the standard M44f attributes `worldToCamera` and `worldToNDC` (16 floats in
// glm::value_ptr order), string attributes `shadowlab:technique`, `shadowlab:depthFormat`, `shadowlab:encoding`,
// and for maps built from several passes (cube faces, cascades, pyramid regions) one group per pass:
//
//   shadowlab:passCount          int     number of passes (0: the map is one pass described by the above)
//   shadowlab:pass<i>:viewport   box2i   the pass's glViewport in the map: min = (x, y), max = (x + w − 1,
//                                        y + h − 1), GL window pixels with the origin at the lower left (the
//                                        file's last row is y = 0)
//   shadowlab:pass<i>:worldToCamera  m44f  the pass's view matrix
//   shadowlab:pass<i>:worldToNDC     m44f  the pass's projection × view
//   shadowlab:pass<i>:label      string  optional name of the pass ("+X", "cascade0", ...)
//
// In memory a map is GL-ordered: row 0 is the bottom row (t = 0).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "raster/state.h"
#include "raster/target.h"
#include "scenes/io/atomic_write.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

struct MapPass {
  std::string label;
  raster::Rect viewport;
  glm::mat4 world_to_camera{1.0f};
  glm::mat4 world_to_ndc{1.0f};
};

struct ExrMap {
  int width = 0, height = 0;
  std::vector<float> z;  // width × height, row 0 at the bottom (GL order)
  glm::mat4 world_to_camera{1.0f};
  glm::mat4 world_to_ndc{1.0f};
  std::string technique;
  std::string depth_format;               // d16, d24 or d32f: the depth buffer the map was rendered into
  std::string encoding = "window-depth";  // window-depth, radial-distance, ...
  std::vector<MapPass> passes;
  // Read back only: the channel the values came from, and whether the file carried each matrix (a map from
  // another renderer may not: the matrices then stay identity and are reported as unset).
  std::string channel = "Z";
  bool has_world_to_camera = false, has_world_to_ndc = false;

  float at(int x, int y) const { return z[size_t(y) * size_t(width) + size_t(x)]; }
};

// A map holding what the depth buffer stores, as a float in [0, 1] (d16, d24: code / max code), with
// depth_format taken from the target; the caller fills matrices, technique and passes.
ExrMap exr_map_from(const raster::DepthTarget& target);
// A map from one channel of a colour target (a distance map rendered into RGBA32F, say); depth_format and
// encoding are left for the caller.
ExrMap exr_map_from(const raster::ColorTarget& target, int channel = 0);

// Writes the map (ZIP-compressed, lossless) through a temporary file. Throws IoError when z does not hold
// width × height values, depth_format is not d16, d24 or d32f, a pass viewport lies outside the map, or the
// file cannot be written.
void write_exr_map(const std::filesystem::path& path, const ExrMap& map);
// The same, staged in `batch` (it replaces `path` when the batch commits).
void write_exr_map(WriteBatch& batch, const std::filesystem::path& path, const ExrMap& map);

// Reads a map written by write_exr_map (or any scanline or tiled EXR with the channel `channel`, of any pixel
// type, converted to float: missing shadowlab attributes read as empty strings and identity matrices). Throws
// IoError when the file cannot be read, has no such channel, or names passes whose attributes are missing.
ExrMap read_exr_map(const std::filesystem::path& path, const std::string& channel = "Z");

// The channel names of an EXR file, in the file's (alphabetical) order. Throws IoError.
std::vector<std::string> exr_channel_names(const std::filesystem::path& path);

SHADOWLAB_ISA_END
}  // namespace scenes::io
