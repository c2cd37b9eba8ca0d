// The base-colour textures a scene's materials name (Material::texture), loaded once per scene through
// material_texture.h (sRGB, mipmapped) and shared by every frame, pass and draw that reads them: the camera
// pass samples colour and alpha, the shadow depth passes and the ray-cast reference the alpha of masked ones.
#pragma once
#include <cstdint>
#include <vector>

#include "scenes/scene.h"
#include "shading/surface_texture.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

struct SceneTextures {
  std::vector<shading::Texture2D> base_color;  // per Scene::materials entry; empty() where it names none
  // The material's texture, or null where it has none.
  const shading::Texture2D* of(uint32_t material) const {
    return material < base_color.size() && !base_color[material].empty() ? &base_color[material] : nullptr;
  }
};

// Loads every material's texture, each file once however many materials name it. A missing or unreadable file
// throws IoError naming the file and the first material that names it.
SceneTextures load_scene_textures(const Scene& scene);

// Every material's base colour as shaders read it (per Scene::materials entry): factor, texture (from
// `textures`, null where none), transform, wraps and, for masked and blend materials, the alpha test.
std::vector<shading::SurfaceTexture> surface_textures(const Scene& scene, const SceneTextures& textures);

// Whether any material names a texture (so a frame needs SceneTextures).
bool has_textures(const Scene& scene);

SHADOWLAB_ISA_END
}  // namespace scenes::io
