// glTF materials to scenes::Material (see gltf_materials.h): factors checked against the specification, the
// base-colour texture as a path or embedded bytes, KHR_texture_transform, sampler wrap modes, alpha modes.
#include "scenes/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "scenes/gltf_json_check.h"
#include "scenes/scene_error.h"

namespace scenes::gltf {
namespace {

std::string indexed(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

}  // namespace

GltfMaterials::GltfMaterials(const tinygltf::Model& model, DataUriImages data_uri_images, std::string file,
                             std::filesystem::path dir, std::vector<Material>& out)
    : model_(model), data_uri_images_(std::move(data_uri_images)), file_(std::move(file)), dir_(std::move(dir)),
      out_(out), materials_(model.materials.size(), -1) {}

void GltfMaterials::fail(const std::string& key, const std::string& message) const {
  throw SceneError(file_, key, message);
}

uint32_t GltfMaterials::material(int index, const std::string& where) {
  if (index < 0) {
    if (!default_material_) {
      out_.push_back(Material{});
      default_material_ = uint32_t(out_.size() - 1);
    }
    return *default_material_;
  }
  if (size_t(index) >= model_.materials.size())
    fail(where + ".material", "material " + std::to_string(index) + " does not exist");
  if (materials_[size_t(index)] >= 0) return uint32_t(materials_[size_t(index)]);
  const tinygltf::Material& src = model_.materials[size_t(index)];
  const std::string key = indexed("materials", size_t(index));
  Material m;
  m.name = src.name.empty() ? key : src.name;
  const auto& pbr = src.pbrMetallicRoughness;
  // glTF's factors lie in [0, 1]; outside it a colour no surface has (the JSON reader refuses it too).
  const auto unit = [](double v) { return v >= 0.0 && v <= 1.0; };
  if (pbr.baseColorFactor.size() != 4 || !std::all_of(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), unit))
    fail(key + ".pbrMetallicRoughness.baseColorFactor", "needs four components, each in [0, 1]");
  if (!unit(pbr.roughnessFactor)) fail(key + ".pbrMetallicRoughness.roughnessFactor", "must lie in [0, 1]");
  if (!unit(pbr.metallicFactor)) fail(key + ".pbrMetallicRoughness.metallicFactor", "must lie in [0, 1]");
  m.base_color = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
  const float roughness = float(pbr.roughnessFactor);
  m.specular_strength = 0.3f * (1.0f - roughness);
  m.shininess = roughness > 0.0f ? std::clamp(2.0f / std::pow(roughness, 4.0f) - 2.0f, 1.0f, 512.0f) : 512.0f;
  m.double_sided = src.doubleSided;
  const std::string tex_key = key + ".pbrMetallicRoughness.baseColorTexture";
  texture_source(pbr.baseColorTexture.index, tex_key, m);
  if (!m.texture.empty()) {
    m.texture_transform = texture_transform(pbr.baseColorTexture, tex_key);
    const int sampler = model_.textures[size_t(pbr.baseColorTexture.index)].sampler;
    if (sampler >= 0) {
      if (size_t(sampler) >= model_.samplers.size())
        fail(indexed("textures", size_t(pbr.baseColorTexture.index)) + ".sampler",
             "sampler " + std::to_string(sampler) + " does not exist");
      const tinygltf::Sampler& smp = model_.samplers[size_t(sampler)];
      const std::string skey = indexed("samplers", size_t(sampler));
      m.wrap_s = wrap_mode(smp.wrapS, skey + ".wrapS");
      m.wrap_t = wrap_mode(smp.wrapT, skey + ".wrapT");
    }
  }
  if (src.alphaMode == "MASK") m.alpha_mode = AlphaMode::mask;
  else if (src.alphaMode == "BLEND") m.alpha_mode = AlphaMode::blend;
  else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
    fail(key + ".alphaMode", "unknown alpha mode '" + src.alphaMode + "' (known: OPAQUE, MASK, BLEND)");
  m.alpha_cutoff = float(src.alphaCutoff);
  if (!(m.alpha_cutoff >= 0.0f) || !std::isfinite(m.alpha_cutoff))
    fail(key + ".alphaCutoff", "must be a number of 0 or more");
  out_.push_back(m);
  materials_[size_t(index)] = int(out_.size() - 1);
  return uint32_t(materials_[size_t(index)]);
}

bool GltfMaterials::has_base_texture(int material) const {
  return material >= 0 && size_t(material) < model_.materials.size() &&
         model_.materials[size_t(material)].pbrMetallicRoughness.baseColorTexture.index >= 0;
}

int GltfMaterials::texcoord_set(int material) const {
  if (material < 0 || size_t(material) >= model_.materials.size()) return 0;
  const tinygltf::TextureInfo& info = model_.materials[size_t(material)].pbrMetallicRoughness.baseColorTexture;
  if (info.index < 0) return 0;
  int set = std::max(info.texCoord, 0);
  if (const auto it = info.extensions.find("KHR_texture_transform"); it != info.extensions.end())
    if (it->second.Has("texCoord") && it->second.Get("texCoord").IsNumber())
      set = std::max(int(it->second.Get("texCoord").GetNumberAsInt()), 0);
  return set;
}

// KHR_texture_transform's matrix T = translation · rotation · scale on glTF's (u, v), taken into GL's
// (s, t) = (u, 1 − v) as F · T · F with F the flip (F is its own inverse).
glm::mat3 GltfMaterials::texture_transform(const tinygltf::TextureInfo& info, const std::string& key) const {
  const auto it = info.extensions.find("KHR_texture_transform");
  if (it == info.extensions.end()) return glm::mat3(1.0f);
  const tinygltf::Value& x = it->second;
  const std::string where = key + ".extensions.KHR_texture_transform";
  auto pair = [&](const char* name, glm::vec2 fallback) {
    if (!x.Has(name)) return fallback;
    const tinygltf::Value& v = x.Get(name);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
      fail(where + "." + name, "expected an array of 2 numbers");
    const glm::vec2 r(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
    if (!std::isfinite(r.x) || !std::isfinite(r.y)) fail(where + "." + name, "must be finite");
    return r;
  };
  const glm::vec2 offset = pair("offset", glm::vec2(0.0f)), scale = pair("scale", glm::vec2(1.0f));
  float rotation = 0.0f;
  if (x.Has("rotation")) {
    if (!x.Get("rotation").IsNumber()) fail(where + ".rotation", "expected a number");
    rotation = float(x.Get("rotation").GetNumberAsDouble());
    if (!std::isfinite(rotation)) fail(where + ".rotation", "must be finite");
  }
  const float c = std::cos(rotation), s = std::sin(rotation);
  // Column-major, as the extension's GLSL writes them.
  const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
  const glm::mat3 r(c, s, 0, -s, c, 0, 0, 0, 1);
  const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
  const glm::mat3 flip(1, 0, 0, 0, -1, 0, 0, 1, 1);  // (u, v) -> (u, 1 - v)
  return flip * (t * r * sc) * flip;
}

TextureWrap GltfMaterials::wrap_mode(int gl, const std::string& key) const {
  switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::mirrored_repeat;
    default: fail(key, "unknown wrap mode " + std::to_string(gl));
  }
}

// Sets the material's texture from glTF texture `texture`: a path for an image in a file of its own, or the
// encoded bytes of one the file embeds (buffer view or data: URI), read once per image.
void GltfMaterials::texture_source(int texture, const std::string& key, Material& m) {
  if (texture < 0) return;
  if (size_t(texture) >= model_.textures.size()) fail(key, "texture " + std::to_string(texture) + " does not exist");
  const int source = model_.textures[size_t(texture)].source;
  if (source < 0) return;
  if (size_t(source) >= model_.images.size())
    fail(indexed("textures", size_t(texture)), "image " + std::to_string(source) + " does not exist");
  const tinygltf::Image& image = model_.images[size_t(source)];
  const std::string where = indexed("images", size_t(source));
  if (image.bufferView < 0 && !image.uri.empty()) {
    m.texture = (dir_ / gltf_uri_decode(image.uri)).lexically_normal().generic_string();
    return;
  }
  auto [it, fresh] = embedded_.try_emplace(source);
  if (fresh) {
    auto e = std::make_shared<EmbeddedImage>();
    e->file = file_;
    e->where = where;
    e->bytes = image.bufferView >= 0 ? view_bytes(image.bufferView, where) : data_uri_bytes(source, where);
    it->second = std::move(e);
  }
  m.texture = file_ + "#" + where;
  m.embedded_texture.image = it->second;
}

// The bytes of buffer view `view`, checked against its buffer (tinygltf does not check an image's view).
std::vector<uint8_t> GltfMaterials::view_bytes(int view, const std::string& where) const {
  if (size_t(view) >= model_.bufferViews.size())
    fail(where + ".bufferView", "buffer view " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& v = model_.bufferViews[size_t(view)];
  const std::string vkey = indexed("bufferViews", size_t(view));
  if (v.buffer < 0 || size_t(v.buffer) >= model_.buffers.size())
    fail(vkey + ".buffer", "buffer " + std::to_string(v.buffer) + " does not exist");
  const std::vector<unsigned char>& data = model_.buffers[size_t(v.buffer)].data;
  if (v.byteLength == 0) fail(vkey + ".byteLength", "an image's buffer view is empty");
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
    fail(vkey, "bytes " + std::to_string(v.byteOffset) + ".." + std::to_string(v.byteOffset + v.byteLength) +
                   " lie past the end of buffer " + std::to_string(v.buffer) + " (" +
                   std::to_string(data.size()) + " bytes)");
  const auto first = data.begin() + std::ptrdiff_t(v.byteOffset);
  return {first, first + std::ptrdiff_t(v.byteLength)};
}

std::vector<uint8_t> GltfMaterials::data_uri_bytes(int source, const std::string& where) const {
  const auto it = data_uri_images_.find(source);
  if (it == data_uri_images_.end() || it->second.empty())
    fail(where + ".uri", "the image has neither a uri with data nor a buffer view");
  return {it->second.begin(), it->second.end()};
}

}  // namespace scenes::gltf
