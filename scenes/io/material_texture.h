// Material textures (PNG, JPEG, EXR, anything OpenImageIO reads) loaded into a shading::Texture2D. Rows are
// flipped into GL order: t = 0 is the bottom row of the picture as a viewer shows it (the file's last row).
// glTF's v runs from the top, so a glTF loader samples at t = 1 − v.
#pragma once
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

struct TextureLoadOptions {
  // 8- and 16-bit integer images hold sRGB colour (base colour, emissive); false for data (normals,
  // roughness, masks), which is then taken as linear.
  bool srgb = true;
  bool mipmaps = true;  // box-filtered chain (shading/mip_chain.h)
};

// 8-bit images become rgba8_srgb (or rgba8 when !srgb) with their bytes unchanged; half-float images rgba16f;
// everything else (16-bit integers, floats) rgba32f, sRGB-decoded when integer and srgb. One channel is grey
// (v, v, v, 1), two grey and alpha, three RGB with alpha 1; channels past four are ignored. Throws IoError.
shading::Texture2D load_texture(const std::filesystem::path& path, const TextureLoadOptions& options = {});

// The same for an encoded image held in memory (a glTF file's embedded PNG or JPEG, told apart by its first
// bytes; anything else is refused). Errors are IoError(file, where + ": " + what is wrong).
shading::Texture2D load_texture(std::span<const uint8_t> bytes, const std::filesystem::path& file,
                                const std::string& where, const TextureLoadOptions& options = {});

SHADOWLAB_ISA_END
}  // namespace scenes::io
