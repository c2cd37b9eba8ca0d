// Test helper: builds tiny glTF 2.0 files (JSON + .bin, or GLB) from raw arrays, so importer tests can make
// exactly the case they need (strips, fans, mirrored nodes, NaN data, broken headers) in a temporary folder.
#pragma once
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace testsupport {

class GltfFixture {
 public:
  GltfFixture() {
    doc["asset"] = {{"version", "2.0"}};
    for (const char* k : {"accessors", "bufferViews", "meshes", "nodes"}) doc[k] = nlohmann::json::array();
    doc["scenes"] = nlohmann::json::array({{{"nodes", nlohmann::json::array()}}});
    doc["scene"] = 0;
  }

  // Appends raw data as a buffer view (e.g. an embedded image's bytes); returns the view's index.
  int buffer_view(const void* data, size_t bytes) {
    while (bin.size() % 4) bin.push_back(0);
    const size_t offset = bin.size();
    bin.resize(offset + bytes);
    if (bytes) std::memcpy(bin.data() + offset, data, bytes);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    return int(doc["bufferViews"].size() - 1);
  }

  // Appends raw data as a buffer view plus an accessor over it; returns the accessor index.
  int accessor(const void* data, size_t bytes, int component_type, size_t count, const std::string& type) {
    doc["accessors"].push_back({{"bufferView", buffer_view(data, bytes)},
                                {"componentType", component_type},
                                {"count", count},
                                {"type", type}});
    return int(doc["accessors"].size() - 1);
  }
  int positions(const std::vector<glm::vec3>& p) {
    return accessor(p.data(), p.size() * sizeof(glm::vec3), 5126, p.size(), "VEC3");
  }
  int normals(const std::vector<glm::vec3>& n) { return positions(n); }
  int indices(const std::vector<uint32_t>& i) { return accessor(i.data(), i.size() * 4, 5125, i.size(), "SCALAR"); }
  int indices16(const std::vector<uint16_t>& i) {
    return accessor(i.data(), i.size() * 2, 5123, i.size(), "SCALAR");
  }

  // A mesh with one primitive; `indices` < 0: non-indexed. Returns the mesh index.
  int mesh(int position_accessor, int index_accessor = -1, int mode = 4, int normal_accessor = -1) {
    nlohmann::json prim = {{"attributes", {{"POSITION", position_accessor}}}, {"mode", mode}};
    if (normal_accessor >= 0) prim["attributes"]["NORMAL"] = normal_accessor;
    if (index_accessor >= 0) prim["indices"] = index_accessor;
    doc["meshes"].push_back({{"primitives", nlohmann::json::array({prim})}});
    return int(doc["meshes"].size() - 1);
  }

  // A root node (added to scene 0) with extra members, e.g. {"mesh", 0}, {"scale", {-1, 1, 1}}.
  int node(nlohmann::json members, bool root = true) {
    doc["nodes"].push_back(std::move(members));
    const int index = int(doc["nodes"].size() - 1);
    if (root) doc["scenes"][0]["nodes"].push_back(index);
    return index;
  }

  // name.gltf + name.bin; returns the .gltf path.
  std::filesystem::path write_gltf(const std::filesystem::path& dir, const std::string& name) {
    nlohmann::json d = doc;
    d["buffers"] = nlohmann::json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}});
    std::ofstream(dir / (name + ".bin"), std::ios::binary).write(reinterpret_cast<const char*>(bin.data()),
                                                                 std::streamsize(bin.size()));
    std::ofstream(dir / (name + ".gltf")) << d.dump(1);
    return dir / (name + ".gltf");
  }

  // The GLB bytes: header, JSON chunk, BIN chunk.
  std::vector<uint8_t> glb_bytes() const {
    nlohmann::json d = doc;
    std::vector<uint8_t> body = bin;
    while (body.size() % 4) body.push_back(0);
    d["buffers"] = nlohmann::json::array({{{"byteLength", body.size()}}});
    std::string json = d.dump();
    while (json.size() % 4) json.push_back(' ');
    std::vector<uint8_t> out;
    out.reserve(28 + json.size() + body.size());
    auto u32 = [&](uint32_t v) {
      for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
    };
    u32(0x46546C67u);  // "glTF"
    u32(2);
    u32(uint32_t(12 + 8 + json.size() + 8 + body.size()));
    u32(uint32_t(json.size()));
    u32(0x4E4F534Au);
    for (char c : json) out.push_back(uint8_t(c));
    u32(uint32_t(body.size()));
    u32(0x004E4942u);
    for (uint8_t b : body) out.push_back(b);
    return out;
  }

  std::filesystem::path write_glb(const std::filesystem::path& dir, const std::string& name) const {
    return write_bytes(dir / (name + ".glb"), glb_bytes());
  }

  static std::filesystem::path write_bytes(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                std::streamsize(bytes.size()));
    return path;
  }

  nlohmann::json doc;
  std::vector<uint8_t> bin;
};

}  // namespace testsupport
