// glTF JSON indices and byte counts checked before tinygltf reads them (see gltf_json_check.h).
#include "scenes/gltf_json_check.h"

#include <cctype>
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

namespace scenes {
namespace {

using nlohmann::json;

enum class Kind { none, index, count, mode };

Kind kind_of(std::string_view key) {
  static constexpr std::string_view kIndices[] = {
      "buffer", "bufferView", "camera", "children", "indices", "index",  "inverseBindMatrices", "joints", "light",
      "material", "mesh",   "node",   "nodes",    "input",   "output", "sampler", "scene", "skeleton", "skin",
      "source", "texCoord"};
  static constexpr std::string_view kCounts[] = {"byteOffset", "byteLength", "byteStride", "count"};
  for (std::string_view k : kIndices)
    if (k == key) return Kind::index;
  for (std::string_view k : kCounts)
    if (k == key) return Kind::count;
  return key == "mode" ? Kind::mode : Kind::none;
}

// The array an index property points into, where that is the same wherever the property appears ("sampler"
// and "index" are left out: an animation's sampler is its own, and an index is only checked as a number).
const char* target_of(std::string_view key) {
  static constexpr std::pair<std::string_view, const char*> kTargets[] = {
      {"mesh", "meshes"},          {"skin", "skins"},           {"camera", "cameras"},
      {"material", "materials"},   {"skeleton", "nodes"},       {"joints", "nodes"},
      {"children", "nodes"},       {"node", "nodes"},           {"nodes", "nodes"},
      {"indices", "accessors"},    {"inverseBindMatrices", "accessors"}, {"input", "accessors"},
      {"output", "accessors"},     {"attributes", "accessors"}, {"targets", "accessors"},
      {"bufferView", "bufferViews"}, {"buffer", "buffers"},     {"source", "images"},
      {"scene", "scenes"},         {"light", "lights"}};
  for (const auto& [k, array] : kTargets)
    if (k == key) return array;
  return nullptr;
}

std::string shown(const json& v) {
  std::string s = v.dump();
  return s.size() > 40 ? s.substr(0, 40) + "..." : s;
}

class Walk {
 public:
  explicit Walk(const json& doc) {
    for (const char* array : {"meshes", "skins", "cameras", "materials", "nodes", "accessors", "bufferViews",
                              "buffers", "images", "scenes"})
      sizes_[array] = doc.contains(array) && doc[array].is_array() ? doc[array].size() : 0;
    const json* lights = nullptr;
    if (doc.contains("extensions") && doc["extensions"].is_object() &&
        doc["extensions"].contains("KHR_lights_punctual") && doc["extensions"]["KHR_lights_punctual"].is_object() &&
        doc["extensions"]["KHR_lights_punctual"].contains("lights"))
      lights = &doc["extensions"]["KHR_lights_punctual"]["lights"];
    sizes_["lights"] = lights && lights->is_array() ? lights->size() : 0;
  }
  std::optional<GltfJsonProblem> problem;

  void value(const json& v, const std::string& at) {
    if (problem) return;
    if (v.is_object()) {
      for (const auto& [key, child] : v.items()) {
        const std::string here = at.empty() ? key : at + "." + key;
        if (key == "extras") continue;
        if (key == "extensions" && child.is_object()) {
          // Only the extensions the importer reads: the others give these keys their own meanings (Draco's
          // "attributes" are ids in its stream, meshopt's byteStride may be 2, KHR_interactivity's "node" is a
          // graph node, EXT_lights_image_based's "light" is not a KHR light, KHR_xmp_json_ld holds free JSON-LD).
          for (const auto& [name, ext] : child.items())
            if (name == "KHR_lights_punctual" || name == "KHR_texture_transform") value(ext, here + "." + name);
          continue;
        }
        if (key == "attributes" && child.is_object()) {
          for (const auto& [name, id] : child.items()) number(id, here + "." + name, Kind::index, "accessors");
          continue;
        }
        if (key == "targets" && child.is_array()) {  // morph targets: objects of attribute -> accessor
          for (size_t i = 0; i < child.size(); ++i)
            if (child[i].is_object())
              for (const auto& [name, id] : child[i].items())
                number(id, here + "[" + std::to_string(i) + "]." + name, Kind::index, "accessors");
          continue;
        }
        const Kind k = kind_of(key);
        const char* array = k == Kind::index ? target_of(key) : nullptr;
        // At the top level only "scene" is an index ("nodes" there is the array of node objects); a sparse
        // accessor's "indices" is an object of its own.
        const bool numeric = k != Kind::none && (!at.empty() || key == "scene") && !(key == "indices" && child.is_object());
        const bool list = key == "children" || key == "nodes" || key == "joints";  // arrays of indices
        if (numeric && list && !child.is_array())
          problem = GltfJsonProblem{here, shown(child) + " is not an array of indices"};
        else if (numeric && list)
          for (size_t i = 0; i < child.size(); ++i) number(child[i], here + "[" + std::to_string(i) + "]", k, array);
        else if (numeric)
          number(child, here, k, array, key == "byteStride");
        else
          value(child, here);  // objects, arrays of objects, everything else
        if (problem) return;
      }
    } else if (v.is_array()) {
      for (size_t i = 0; i < v.size() && !problem; ++i) value(v[i], at + "[" + std::to_string(i) + "]");
    }
  }

 private:
  std::map<std::string, size_t, std::less<>> sizes_;  // the top-level arrays' lengths

  void number(const json& v, const std::string& at, Kind k, const char* array = nullptr, bool stride = false) {
    if (problem) return;
    const double d = v.is_number() ? v.get<double>() : -1.0;  // a string, object or null where a number belongs
    const double top = k == Kind::count ? 9007199254740992.0 : double(std::numeric_limits<int32_t>::max());
    const bool whole = std::isfinite(d) && d == std::floor(d) && d >= 0.0 && d <= top;
    if (k == Kind::mode) {
      if (!whole || d > 6.0)
        problem = GltfJsonProblem{at, shown(v) + " is not a primitive mode (0 points .. 6 triangle fan)"};
    } else if (!whole) {
      problem = GltfJsonProblem{at, shown(v) + (k == Kind::index ? " is not an index (a whole number from 0 to 2147483647)"
                                                                  : " is not a whole number of 0 or more")};
    } else if (stride && !(d >= 4.0 && d <= 252.0 && std::fmod(d, 4.0) == 0.0)) {
      problem = GltfJsonProblem{at, shown(v) + " is not a byte stride glTF allows (a multiple of 4 from 4 to 252)"};
    } else if (array && d >= double(sizes_.find(array)->second)) {
      const size_t n = sizes_.find(array)->second;
      problem = GltfJsonProblem{at, "index " + shown(v) + " is past the end of " + array + " (the file has " +
                                        std::to_string(n) + (n == 1 ? " entry)" : " entries)")};
    }
  }
};

// Brackets nested deeper than this are refused before any parser sees them: tinygltf copies the document
// recursively, a frame per level, and 30,000 levels overflowed the stack (a glTF file nests some ten).
constexpr int kMaxNesting = 256;

bool nests_too_deep(const unsigned char* text, size_t size) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < size; ++i) {
    const unsigned char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

// An accessor's required "type" and "componentType" (glTF 3.6.2: tinygltf names neither when one is wrong), and
// a sparse accessor's index component type.
std::optional<GltfJsonProblem> accessor_problem(const json& a, const std::string& at) {
  static constexpr std::string_view kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
  if (!a.is_object()) return GltfJsonProblem{at, "is not an object"};
  for (const char* key : {"componentType", "count", "type"})
    if (!a.contains(key)) return GltfJsonProblem{at + "." + key, "missing (an accessor needs it)"};
  const json& type = a["type"];
  bool known = false;
  if (type.is_string())
    for (std::string_view t : kTypes) known |= type.get<std::string>() == t;
  if (!known) return GltfJsonProblem{at + ".type", shown(type) + " is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4"};
  auto component = [&](const json& c, const std::string& where, std::initializer_list<int> allowed,
                       const char* names) -> std::optional<GltfJsonProblem> {
    bool ok = false;
    for (int v : allowed) ok |= c.is_number() && c.get<double>() == double(v);
    if (!ok) return GltfJsonProblem{where, shown(c) + " is not a component type glTF allows (" + names + ")"};
    return std::nullopt;
  };
  if (auto p = component(a["componentType"], at + ".componentType", {5120, 5121, 5122, 5123, 5125, 5126},
                         "5120 byte, 5121 unsigned byte, 5122 short, 5123 unsigned short, 5125 unsigned int, 5126 float"))
    return p;
  if (a.contains("sparse") && a["sparse"].is_object() && a["sparse"].contains("indices") &&
      a["sparse"]["indices"].is_object()) {
    const json& indices = a["sparse"]["indices"];
    if (!indices.contains("componentType"))
      return GltfJsonProblem{at + ".sparse.indices.componentType", "missing (sparse indices need it)"};
    if (auto p = component(indices["componentType"], at + ".sparse.indices.componentType", {5121, 5123, 5125},
                           "5121 unsigned byte, 5123 unsigned short, 5125 unsigned int"))
      return p;
  }
  return std::nullopt;
}

bool base64_text(std::string_view s) {
  for (const char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/' || c == '=')) return false;
  return true;
}

// A buffer's "uri" and "byteLength": every buffer of a .gltf file needs a uri, in a .glb file all but the first
// (which may be the BIN chunk); a data: URI holds base64; a file must be there (`dir`: the glTF file's folder).
std::optional<GltfJsonProblem> buffer_problem(const json& b, const std::string& at, bool may_be_chunk,
                                              const std::filesystem::path* dir) {
  if (!b.is_object()) return GltfJsonProblem{at, "is not an object"};
  if (!b.contains("byteLength")) return GltfJsonProblem{at + ".byteLength", "missing (a buffer needs it)"};
  if (!b.contains("uri")) {
    if (may_be_chunk) return std::nullopt;
    return GltfJsonProblem{at + ".uri", "missing (only the first buffer of a .glb file may leave it out, for the file's "
                                        "BIN chunk)"};
  }
  const json& uri = b["uri"];
  if (!uri.is_string() || uri.get<std::string>().empty())
    return GltfJsonProblem{at + ".uri", shown(uri) + " is not a file name or a data: URI"};
  const std::string text = uri.get<std::string>();
  if (text.rfind("data:", 0) == 0) {
    // The media types tinygltf decodes (glTF names the first two for buffers); any other it takes for a file name.
    static constexpr std::string_view kTypes[] = {"application/octet-stream", "application/gltf-buffer", "image/jpeg",
                                                  "image/png", "image/bmp", "image/gif", "text/plain"};
    const size_t comma = text.find(',');
    const size_t base64 = text.find(";base64,");
    if (comma == std::string::npos || base64 == std::string::npos || base64 + 7 != comma ||
        !base64_text(std::string_view(text).substr(comma + 1)))
      return GltfJsonProblem{at + ".uri", "a data: URI whose data is not base64 (data:application/octet-stream;base64,...)"};
    const std::string_view type = std::string_view(text).substr(5, base64 - 5);
    bool known = false;
    for (std::string_view t : kTypes) known |= t == type;
    if (!known)
      return GltfJsonProblem{at + ".uri", "a data: URI of type '" + std::string(type) +
                                          "' (a buffer's is application/octet-stream or application/gltf-buffer)"};
    // The bytes it holds must be the buffer's byteLength (tinygltf refuses any other count).
    const std::string_view data = std::string_view(text).substr(comma + 1);
    const size_t pad = data.size() - std::min(data.find('='), data.size());
    const double held = double(data.size() / 4 * 3 + (data.size() % 4 ? data.size() % 4 - 1 : 0)) - double(pad);
    if (b["byteLength"].is_number() && b["byteLength"].get<double>() != held)
      return GltfJsonProblem{at + ".uri", "the data: URI holds " + std::to_string(size_t(std::max(held, 0.0))) +
                                          " bytes, byteLength says " + shown(b["byteLength"])};
    return std::nullopt;
  }
  if (dir) {
    const std::filesystem::path file = *dir / gltf_uri_decode(text);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      return GltfJsonProblem{at + ".uri", "'" + text + "': " +
                                          (std::filesystem::exists(file, ec) ? "not a regular file" : "no such file") +
                                          " (looked for " + file.generic_string() + ")"};
  }
  return std::nullopt;
}

}  // namespace

std::string gltf_uri_decode(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    const bool escape = uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
                        std::isxdigit(static_cast<unsigned char>(uri[i + 2]));
    if (escape) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::optional<GltfJsonProblem> gltf_json_problem(const unsigned char* bytes, size_t length, bool binary,
                                                 const std::filesystem::path* dir) {
  const unsigned char* text = bytes;
  size_t size = length;
  if (binary) {  // 12-byte header, then the JSON chunk: length, type "JSON", data
    if (length < 20) return std::nullopt;
    auto u32 = [&](size_t at) {
      return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
             uint32_t(bytes[at + 3]) << 24;
    };
    const uint32_t chunk = u32(12);
    if (u32(16) != 0x4E4F534Au || chunk > length - 20) return std::nullopt;
    text = bytes + 20, size = chunk;
  }
  if (nests_too_deep(text, size))
    return GltfJsonProblem{"", "the JSON nests deeper than " + std::to_string(kMaxNesting) + " levels"};
  const json doc = json::parse(text, text + size, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
  Walk w(doc);
  w.value(doc, "");
  if (w.problem) return w.problem;
  if (doc.contains("accessors") && doc["accessors"].is_array())
    for (size_t i = 0; i < doc["accessors"].size(); ++i)
      if (auto p = accessor_problem(doc["accessors"][i], "accessors[" + std::to_string(i) + "]")) return p;
  if (doc.contains("buffers") && doc["buffers"].is_array())
    for (size_t i = 0; i < doc["buffers"].size(); ++i)
      if (auto p = buffer_problem(doc["buffers"][i], "buffers[" + std::to_string(i) + "]", binary && i == 0, dir))
        return p;
  // glTF 3.6.2.3: "normalized" is for 8- and 16-bit integer components only (read as a float or a 32-bit
  // integer, the flag would be ignored).
  if (doc.contains("accessors") && doc["accessors"].is_array())
    for (size_t i = 0; i < doc["accessors"].size(); ++i) {
      const json& a = doc["accessors"][i];
      if (a.is_object() && a.contains("normalized") && a["normalized"] == true && a.contains("componentType") &&
          a["componentType"].is_number() && (a["componentType"] == 5125 || a["componentType"] == 5126))
        return GltfJsonProblem{"accessors[" + std::to_string(i) + "].normalized",
                               "only 8- and 16-bit integer components can be normalized"};
    }
  // A node with a matrix and a translation, rotation or scale: tinygltf keeps the matrix and drops the rest.
  if (doc.contains("nodes") && doc["nodes"].is_array())
    for (size_t i = 0; i < doc["nodes"].size(); ++i) {
      const json& n = doc["nodes"][i];
      if (n.is_object() && n.contains("matrix") && (n.contains("translation") || n.contains("rotation") || n.contains("scale")))
        return GltfJsonProblem{"nodes[" + std::to_string(i) + "].matrix",
                               "a node has a matrix or translation, rotation and scale, not both"};
    }
  return std::nullopt;
}

}  // namespace scenes
