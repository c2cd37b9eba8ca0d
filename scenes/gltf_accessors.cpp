// Checked glTF accessor reads (see gltf_accessors.h): bounds of accessor, buffer view and buffer, component
// types allowed per use, normalized integers, and sparse substitution.
#include "scenes/gltf_accessors.h"

#include <algorithm>
#include <cstring>

#include "scenes/scene_error.h"

namespace scenes::gltf {
namespace {

size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

size_t components_of(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "VEC4";
  }
}

template <typename Raw>
Raw load(const unsigned char* p) {
  Raw v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// One component as a float (normalized integers mapped to [0, 1] or [-1, 1] as glTF specifies).
float as_float(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return normalized ? std::max(load<int8_t>(p) / 127.0f, -1.0f) : load<int8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return normalized ? std::max(load<int16_t>(p) / 32767.0f, -1.0f) : load<int16_t>(p);
    default: return float(load<uint32_t>(p));
  }
}

// Larger accessors are rejected before anything is allocated (2^28 elements: 3 GiB of VEC3 floats).
constexpr size_t kMaxElements = size_t(1) << 28;

// An accessor without a bufferView is all zeros (plus its sparse values): its count costs the file nothing and
// the reader count × element bytes. It may hold no more elements than the file's buffers hold bytes (a mesh's
// real attributes fit in its buffers, so zeros beside them do too), or 65,536 in a file with smaller buffers;
// beyond that a few bytes of JSON would make the reader allocate gigabytes.
constexpr size_t kMinZeroElements = size_t(1) << 16;

uint32_t as_uint(const unsigned char* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
    default: return load<uint32_t>(p);
  }
}

}  // namespace

void AccessorReader::fail(const std::string& key, const std::string& message) const {
  throw SceneError(file_, key, message);
}

const unsigned char* AccessorReader::span_of(int buffer_view, size_t offset, size_t stride, size_t count,
                                             size_t element, const std::string& key) const {
  const std::string bv = "bufferViews[" + std::to_string(buffer_view) + "]";
  if (buffer_view < 0 || size_t(buffer_view) >= model_.bufferViews.size())
    fail(key, "buffer view " + std::to_string(buffer_view) + " does not exist");
  const tinygltf::BufferView& view = model_.bufferViews[size_t(buffer_view)];
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
    fail(bv, "buffer " + std::to_string(view.buffer) + " does not exist");
  const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    fail(bv, "bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                 " lie outside buffer " + std::to_string(view.buffer) + " (" + std::to_string(data.size()) +
                 " bytes)");
  if (count == 0) return data.data();
  const size_t last = offset + (count - 1) * stride + element;  // overflow: counts are bounded by JSON sizes
  if (offset > view.byteLength || last > view.byteLength || (count - 1) > view.byteLength)
    fail(key, std::to_string(count) + " elements at offset " + std::to_string(offset) + " run past the end of " +
                  bv + " (" + std::to_string(view.byteLength) + " bytes)");
  return data.data() + view.byteOffset + offset;
}

template <typename T, typename Alloc>
void AccessorReader::read(int index, const std::string& key, int type, Want want, Alloc&& alloc) const {
  if (index < 0 || size_t(index) >= model_.accessors.size())
    fail(key, "accessor " + std::to_string(index) + " does not exist");
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  const std::string where = key + " (accessors[" + std::to_string(index) + "])";
  if (a.type != type) fail(where, std::string("expected type ") + type_name(type));
  const int ct = a.componentType;
  const size_t n = components_of(type), csize = component_size(ct);
  if (csize == 0) fail(where, "invalid componentType " + std::to_string(ct));
  const bool is_float = ct == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool is_unsigned = ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                           ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT || ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (want == Want::floats && !is_float) fail(where, "expected FLOAT components");
  if (want == Want::floats_or_normalized && !is_float && !(a.normalized && is_unsigned))
    fail(where, "expected FLOAT or normalized unsigned components");
  if (want == Want::unsigned_ints && !is_unsigned) fail(where, "expected unsigned integer components");
  if (want == Want::unsigned_small && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
    fail(where, "expected UNSIGNED_BYTE or UNSIGNED_SHORT components");
  const bool small_signed = ct == TINYGLTF_COMPONENT_TYPE_BYTE || ct == TINYGLTF_COMPONENT_TYPE_SHORT;
  if (want == Want::quantized && ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(where, "expected FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT components");
  if (want == Want::quantized_normal && !is_float && !(small_signed && a.normalized))
    fail(where, "expected FLOAT or normalized BYTE or SHORT components (KHR_mesh_quantization)");
  if (want == Want::quantized_signed && !is_float && !small_signed)
    fail(where, "expected FLOAT, BYTE or SHORT components (KHR_mesh_quantization)");
  if (a.count > kMaxElements) fail(where, "count " + std::to_string(a.count) + " is too large");
  const size_t element = n * csize;

  // Every span is checked before anything is allocated: a count the buffers cannot hold fails here, not after
  // allocating for it.
  const unsigned char* p = nullptr;
  size_t stride = element;
  if (a.bufferView >= 0) {
    if (size_t(a.bufferView) < model_.bufferViews.size() && model_.bufferViews[size_t(a.bufferView)].byteStride)
      stride = model_.bufferViews[size_t(a.bufferView)].byteStride;
    if (stride < element) fail(where, "byteStride " + std::to_string(stride) + " is smaller than an element");
    p = span_of(a.bufferView, a.byteOffset, stride, a.count, element, where);
  } else {
    size_t buffer_bytes = 0;
    for (const tinygltf::Buffer& b : model_.buffers) buffer_bytes += b.data.size();
    const size_t bound = std::max(buffer_bytes, kMinZeroElements);
    if (a.count > bound)
      fail(where, "count " + std::to_string(a.count) + " without a bufferView exceeds " + std::to_string(bound) +
                      " (the elements an accessor of zeros may have: the file's buffer bytes, at least 65536)");
  }
  const size_t sparse = a.sparse.isSparse && a.sparse.count > 0 ? size_t(a.sparse.count) : 0;
  const int it = a.sparse.indices.componentType;
  const size_t isize = component_size(it);
  const unsigned char *ip = nullptr, *vp = nullptr;
  if (sparse) {
    if (sparse > a.count) fail(where + ".sparse", "more sparse values than elements");
    if (isize == 0 || it == TINYGLTF_COMPONENT_TYPE_FLOAT) fail(where + ".sparse.indices", "invalid componentType");
    ip = span_of(a.sparse.indices.bufferView, size_t(a.sparse.indices.byteOffset), isize, sparse, isize,
                 where + ".sparse.indices");
    vp = span_of(a.sparse.values.bufferView, size_t(a.sparse.values.byteOffset), element, sparse, element,
                 where + ".sparse.values");
  }

  T* out = alloc(a.count);
  if (a.count == 0) return;
  auto convert = [&](const unsigned char* q) {
    if constexpr (std::is_same_v<T, uint32_t>) return as_uint(q, ct);
    else return as_float(q, ct, a.normalized);
  };
  if (p) {
    for (size_t i = 0; i < a.count; ++i, p += stride)
      for (size_t c = 0; c < n; ++c) out[i * n + c] = convert(p + c * csize);
  } else {
    std::fill(out, out + a.count * n, T(0));
  }
  for (size_t s = 0; s < sparse; ++s) {
    const uint32_t target = as_uint(ip + s * isize, it);
    if (target >= a.count) fail(where + ".sparse.indices", "index " + std::to_string(target) + " out of range");
    for (size_t c = 0; c < n; ++c) out[target * n + c] = convert(vp + s * element + c * csize);
  }
}

// glm vectors and matrices are tightly packed components, so they are read in place as flat component arrays.
static_assert(sizeof(glm::vec2) == 2 * sizeof(float) && sizeof(glm::vec3) == 3 * sizeof(float) &&
              sizeof(glm::vec4) == 4 * sizeof(float) && sizeof(glm::mat4) == 16 * sizeof(float) &&
              sizeof(glm::uvec4) == 4 * sizeof(uint32_t));

template <typename Element, typename Component>
std::vector<Element> AccessorReader::read_all(int accessor, const std::string& key, int type, Want want) const {
  std::vector<Element> out;
  read<Component>(accessor, key, type, want, [&](size_t n) {
    out.resize(n);
    return n ? reinterpret_cast<Component*>(out.data()) : nullptr;
  });
  return out;
}

std::vector<glm::vec3> AccessorReader::vec3(int accessor, const std::string& key, Quantized quantized) const {
  const Want want = quantized == Quantized::position          ? Want::quantized
                    : quantized == Quantized::normal          ? Want::quantized_normal
                    : quantized == Quantized::target_position ? Want::quantized_signed
                                                              : Want::floats;
  return read_all<glm::vec3, float>(accessor, key, TINYGLTF_TYPE_VEC3, want);
}

std::vector<glm::vec2> AccessorReader::vec2(int accessor, const std::string& key, bool quantized) const {
  return read_all<glm::vec2, float>(accessor, key, TINYGLTF_TYPE_VEC2,
                                    quantized ? Want::quantized : Want::floats_or_normalized);
}

std::vector<uint32_t> AccessorReader::indices(int accessor, const std::string& key) const {
  return read_all<uint32_t, uint32_t>(accessor, key, TINYGLTF_TYPE_SCALAR, Want::unsigned_ints);
}

std::vector<glm::vec4> AccessorReader::weights(int accessor, const std::string& key) const {
  return read_all<glm::vec4, float>(accessor, key, TINYGLTF_TYPE_VEC4, Want::floats_or_normalized);
}

std::vector<glm::uvec4> AccessorReader::joints(int accessor, const std::string& key) const {
  return read_all<glm::uvec4, uint32_t>(accessor, key, TINYGLTF_TYPE_VEC4, Want::unsigned_small);
}

std::vector<glm::mat4> AccessorReader::mat4(int accessor, const std::string& key) const {
  return read_all<glm::mat4, float>(accessor, key, TINYGLTF_TYPE_MAT4, Want::floats);
}

}  // namespace scenes::gltf
