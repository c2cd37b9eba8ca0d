// Reading glTF accessors into typed arrays for the importer, with every index, offset, stride and length checked
// against the buffers first (sparse accessors included), so a malformed file yields a SceneError naming the key,
// never a read out of bounds. Internal to the scenes module: only gltf_import.cpp includes it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace scenes::gltf {

class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, std::string file) : model_(model), file_(std::move(file)) {}

  // What an attribute may hold in a file that uses KHR_mesh_quantization, beside FLOAT: a position or a texture
  // coordinate BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT, normalized or not; a normal (and a morph target's
  // normal) normalized BYTE or SHORT; a morph target's position BYTE or SHORT, normalized or not.
  enum class Quantized { no, position, normal, target_position };
  // VEC3 of FLOAT (positions, normals, morph targets' displacements), or what `quantized` allows.
  std::vector<glm::vec3> vec3(int accessor, const std::string& key, Quantized quantized = Quantized::no) const;
  // VEC2 of FLOAT, or normalized UNSIGNED_BYTE / UNSIGNED_SHORT (texture coordinates); with `quantized`
  // (Quantized::position) any of a quantized position's types.
  std::vector<glm::vec2> vec2(int accessor, const std::string& key, bool quantized = false) const;
  // SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT (indices).
  std::vector<uint32_t> indices(int accessor, const std::string& key) const;
  // VEC4 of FLOAT, or normalized UNSIGNED_BYTE / UNSIGNED_SHORT (skin weights, WEIGHTS_n).
  std::vector<glm::vec4> weights(int accessor, const std::string& key) const;
  // VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT (skin joint indices, JOINTS_n).
  std::vector<glm::uvec4> joints(int accessor, const std::string& key) const;
  // MAT4 of FLOAT, column-major (a skin's inverseBindMatrices).
  std::vector<glm::mat4> mat4(int accessor, const std::string& key) const;

 private:
  enum class Want { floats, floats_or_normalized, unsigned_ints, unsigned_small, quantized, quantized_normal,
                    quantized_signed };
  // Flat components of an accessor of `type` (sparse values applied) into alloc(count), which returns room
  // for count × components values; called only after every bound is checked, so nothing is allocated for a
  // count the buffers cannot hold.
  template <typename T, typename Alloc>
  void read(int accessor, const std::string& key, int type, Want want, Alloc&& alloc) const;
  // Every element of an accessor as Element, a packed array of Component (read's output, sized by it).
  template <typename Element, typename Component>
  std::vector<Element> read_all(int accessor, const std::string& key, int type, Want want) const;
  const unsigned char* span_of(int buffer_view, size_t offset, size_t stride, size_t count, size_t element,
                               const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  const tinygltf::Model& model_;
  std::string file_;
};

}  // namespace scenes::gltf
