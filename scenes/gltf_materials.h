// glTF materials as the importer needs them: each glTF material converted once into a scenes::Material
// (factors in [0, 1], the base-colour texture as a path beside the file or as the encoded bytes of an embedded
// image, its KHR_texture_transform and sampler wrap modes, the alpha mode), and which texture-coordinate set a
// primitive must carry for it. Internal to the scenes module: only gltf_import.cpp includes it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scenes/scene.h"

namespace scenes::gltf {

// The encoded bytes of the images given as data: URIs, by image index (tinygltf decodes the base64 and hands them
// to the image hook; the buffer-view images are read from their views, bounds-checked, here).
using DataUriImages = std::map<int, std::vector<unsigned char>>;

class GltfMaterials {
 public:
  // Materials are appended to `out` as primitives first use them; `dir` is the file's folder, for texture paths.
  GltfMaterials(const tinygltf::Model& model, DataUriImages data_uri_images, std::string file,
                std::filesystem::path dir, std::vector<Material>& out);

  // The index in `out` of glTF material `index` (converted on first use; a default material for -1). `where`
  // names the primitive that refers to it, for errors. Throws SceneError naming the glTF key.
  uint32_t material(int index, const std::string& where);
  // Whether glTF material `material` has a base-colour texture.
  bool has_base_texture(int material) const;
  // The TEXCOORD_n a primitive's material reads its base-colour texture through (KHR_texture_transform's
  // texCoord overrides the texture info's), 0 without a texture.
  int texcoord_set(int material) const;

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  glm::mat3 texture_transform(const tinygltf::TextureInfo& info, const std::string& key) const;
  TextureWrap wrap_mode(int gl, const std::string& key) const;
  void texture_source(int texture, const std::string& key, Material& m);
  std::vector<uint8_t> view_bytes(int view, const std::string& where) const;
  std::vector<uint8_t> data_uri_bytes(int source, const std::string& where) const;

  const tinygltf::Model& model_;
  DataUriImages data_uri_images_;
  std::string file_;
  std::filesystem::path dir_;
  std::vector<Material>& out_;
  std::vector<int> materials_;  // glTF material -> index in out_, -1 until converted
  std::optional<uint32_t> default_material_;
  std::map<int, std::shared_ptr<const EmbeddedImage>> embedded_;  // by image index
};

}  // namespace scenes::gltf
