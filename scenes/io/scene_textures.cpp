// Loading a scene's material textures once (see scene_textures.h).
#include "scenes/io/scene_textures.h"

#include <map>
#include <string>

#include "scenes/io/io_error.h"
#include "scenes/io/material_texture.h"
#include "scenes/scene_queries.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

SceneTextures load_scene_textures(const Scene& scene) {
  SceneTextures out;
  out.base_color.resize(scene.materials.size());
  std::map<std::string, shading::Texture2D> loaded;  // by path: copies share texels
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    if (m.texture.empty()) continue;
    auto it = loaded.find(m.texture);
    if (it == loaded.end()) {
      try {
        if (const auto& e = m.embedded_texture.image)
          it = loaded.emplace(m.texture, load_texture(e->bytes, e->file, e->where)).first;
        else
          it = loaded.emplace(m.texture, load_texture(m.texture)).first;
      } catch (const IoError& e) {
        // Named by the material's name alone: the scene's own index is not the file's (a glTF material without
        // a name is named by its key in the file, `materials[K]`).
        throw IoError(e.file(), "base-colour texture of material '" + m.name + "': " + e.reason());
      }
    }
    out.base_color[i] = it->second;
  }
  return out;
}

namespace {

shading::Wrap wrap_of(TextureWrap w) {
  switch (w) {
    case TextureWrap::repeat: return shading::Wrap::repeat;
    case TextureWrap::clamp_to_edge: return shading::Wrap::clamp_to_edge;
    case TextureWrap::mirrored_repeat: return shading::Wrap::mirrored_repeat;
  }
  return shading::Wrap::repeat;
}

}  // namespace

std::vector<shading::SurfaceTexture> surface_textures(const Scene& scene, const SceneTextures& textures) {
  std::vector<shading::SurfaceTexture> out(scene.materials.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const Material& m = scene.materials[i];
    shading::SurfaceTexture& s = out[i];
    s.texture = textures.of(uint32_t(i));
    s.sampler.wrap_s = wrap_of(m.wrap_s);
    s.sampler.wrap_t = wrap_of(m.wrap_t);
    s.transform = m.texture_transform;
    s.factor = m.base_color;
    s.masked = coverage(m) == Coverage::masked;
    s.cutoff = alpha_cutoff(m);
  }
  return out;
}

bool has_textures(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (!m.texture.empty()) return true;
  return false;
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
