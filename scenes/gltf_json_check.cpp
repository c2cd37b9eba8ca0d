// glTF JSON indices and byte counts checked before tinygltf reads them (see gltf_json_check.h).
#include "scenes/gltf_json_check.h"

#include <cmath>
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
        if (k != Kind::none && child.is_number()) number(child, here, k, array, key == "byteStride");
        else if (k == Kind::index && child.is_array() && !child.empty() && child[0].is_number())
          for (size_t i = 0; i < child.size(); ++i) number(child[i], here + "[" + std::to_string(i) + "]", k, array);
        else value(child, here);  // objects (sparse "indices"), arrays of objects, everything else
        if (problem) return;
      }
    } else if (v.is_array()) {
      for (size_t i = 0; i < v.size() && !problem; ++i) value(v[i], at + "[" + std::to_string(i) + "]");
    }
  }

 private:
  std::map<std::string, size_t, std::less<>> sizes_;  // the top-level arrays' lengths

  void number(const json& v, const std::string& at, Kind k, const char* array = nullptr, bool stride = false) {
    if (problem || !v.is_number()) return;  // a string or object where a number belongs: tinygltf's to report
    const double d = v.get<double>();
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

}  // namespace

std::optional<GltfJsonProblem> gltf_json_problem(const unsigned char* bytes, size_t length, bool binary) {
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
