// glTF 2.0 import (see gltf_import.h): load the file with tinygltf, walk the node hierarchy in double precision,
// convert each referenced primitive once, with its material (gltf_materials.h), then cameras and KHR_lights_punctual
// lights on demand; skinned and morphed nodes are posed once the walk is done (gltf_pose.h).
#include "scenes/gltf_import.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_json_check.h"
#include "scenes/gltf_materials.h"
#include "scenes/gltf_pose.h"
#include "scenes/mesh_ops.h"
#include "scenes/scene_error.h"

namespace scenes {
namespace {

std::string indexed(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

using gltf::DataUriImages;

// tinygltf's image hook: images are never decoded here (scenes/io does that with the other textures); a data:
// URI's bytes are kept, since tinygltf drops them after the call.
bool keep_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                const unsigned char* bytes, int size, void* user) {
  if (image->bufferView < 0 && bytes && size > 0)
    (*static_cast<DataUriImages*>(user))[index].assign(bytes, bytes + size);
  return true;
}

// tinygltf's messages on one line, without nlohmann's "[json.exception.parse_error.101] " tag.
std::string clean_message(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (char& c : s)
    if (c == '\n') c = ' ';
  if (const size_t end = s.find("] "); s.rfind("[json.exception.", 0) == 0 && end != std::string::npos)
    s = s.substr(end + 2);
  // tinygltf quotes a bad data: URI whole (a 240 KB line for a broken buffer): the start says enough.
  if (constexpr size_t kMax = 240; s.size() > kMax) s = s.substr(0, kMax) + "... (" + std::to_string(s.size()) + " characters)";
  return s;
}

tinygltf::Model load_model(const std::filesystem::path& path, const std::string& file, Scene& out,
                           DataUriImages& data_uri_images) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw SceneError(file, "", "cannot open file (" + std::string(std::strerror(errno)) + ")");
  const std::streamoff size = in.tellg();
  if (size < 0) throw SceneError(file, "", "cannot read file");
  if (uint64_t(size) > std::numeric_limits<unsigned int>::max()) throw SceneError(file, "", "file is over 4 GiB");
  // Not a std::vector: zero-filling tens of megabytes only to overwrite them costs as much as reading them.
  const std::unique_ptr<unsigned char[]> bytes(new unsigned char[size_t(size)]);
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.get()), size)) throw SceneError(file, "", "cannot read file");

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image, &data_uri_images);
  // External files (buffers, images) must be regular files: tinygltf's own test accepts a folder (a buffer
  // with uri "." then failed as std::bad_alloc); with this one it reports the file as not found, by name.
  tinygltf::FsCallbacks fs{};
  fs.FileExists = [](const std::string& name, void*) {
    std::error_code ec;
    return std::filesystem::is_regular_file(name, ec);
  };
  fs.ExpandFilePath = &tinygltf::ExpandFilePath;
  fs.ReadWholeFile = &tinygltf::ReadWholeFile;
  fs.WriteWholeFile = &tinygltf::WriteWholeFile;
  loader.SetFsCallbacks(fs);
  tinygltf::Model model;
  std::string err, warn;
  const std::string dir = path.parent_path().empty() ? std::string(".") : path.parent_path().string();
  const auto length = static_cast<unsigned int>(size);
  const bool binary = length >= 4 && std::equal(bytes.get(), bytes.get() + 4, "glTF");
  if (binary && length >= 8) {  // the header's version (little-endian uint32 at byte 4): this reader is glTF 2.0
    const uint32_t version = uint32_t(bytes[4]) | uint32_t(bytes[5]) << 8 | uint32_t(bytes[6]) << 16 |
                             uint32_t(bytes[7]) << 24;
    if (version != 2)
      throw SceneError(file, "", "malformed GLB: header version " + std::to_string(version) +
                                     " (only glTF 2.0 binaries, version 2, are read)");
  }
  const std::filesystem::path folder(dir);
  if (auto p = gltf_json_problem(bytes.get(), length, binary, &folder)) throw SceneError(file, p->key, p->message);
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.get(), length, dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.get()), length,
                                             dir);
  } catch (const std::exception& e) {
    // tinygltf throws on some inconsistent files (issue 23: a GLB buffer of byteLength 0 over a BIN chunk).
    throw SceneError(file, "", std::string(binary ? "malformed GLB: " : "malformed glTF: ") +
                                   "the loader failed on it (" + clean_message(e.what()) + ")");
  }
  if (!ok || !err.empty())
    throw SceneError(file, "", std::string(binary ? "malformed GLB: " : "malformed glTF: ") +
                                   clean_message(err.empty() ? "tinygltf refused it" : err));
  if (!warn.empty()) out.warnings.push_back(file + ": " + clean_message(warn));
  return model;
}

glm::dmat4 node_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());
  glm::dmat4 m(1.0);
  if (n.translation.size() == 3) m = glm::translate(m, glm::make_vec3(n.translation.data()));
  if (n.rotation.size() == 4)
    m = m * glm::mat4_cast(glm::normalize(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2])));
  if (n.scale.size() == 3) m = glm::scale(m, glm::make_vec3(n.scale.data()));
  return m;
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, DataUriImages data_uri_images, std::string file,
           std::filesystem::path dir, Scene& out)
      : model_(model), file_(std::move(file)), out_(out), read_(model, file_),
        materials_(model, std::move(data_uri_images), file_, std::move(dir), out.materials),
        quantized_(std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization") !=
                   model.extensionsUsed.end()) {}

  void run() {
    // A required extension the importer does not read would draw the file wrongly (compressed geometry as
    // accessors without data, another material model's colours): glTF asks a loader to refuse it.
    if (model_.asset.version.rfind("2.", 0) != 0)
      fail("asset.version", "'" + model_.asset.version + "': this importer reads glTF 2.x");
    for (const std::string& ext : model_.extensionsRequired)
      if (std::find(std::begin(kReadExtensions), std::end(kReadExtensions), ext) == std::end(kReadExtensions))
        fail("extensionsRequired", "'" + ext + "' is not supported (this importer reads KHR_lights_punctual, "
                                   "KHR_texture_transform and KHR_mesh_quantization)");
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const size_t s = model_.defaultScene >= 0 ? size_t(model_.defaultScene) : 0;
      if (s >= model_.scenes.size()) fail("scene", "scene " + std::to_string(s) + " does not exist");
      roots = model_.scenes[s].nodes;
    } else {
      std::vector<bool> child(model_.nodes.size(), false);
      for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
      for (size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
    }
    walk(roots);
    for (const Posed& p : posed_) pose(p);
    if (out_.instances.empty()) fail("", "empty mesh: the file's scene has no triangles");
    bool area = false;
    for (const Instance& inst : out_.instances) area = area || has_triangle_with_area(out_.meshes[inst.mesh], inst.transform);
    if (!area) fail("", "every triangle of the file's scene has zero area: nothing would be drawn or cast a shadow");
  }

 private:
  // The extensions whose content the importer reads (quantized attributes are normalized or integer accessors,
  // which gltf_accessors reads): a file may require these.
  static constexpr const char* kReadExtensions[] = {"KHR_lights_punctual", "KHR_texture_transform",
                                                    "KHR_mesh_quantization"};

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw SceneError(file_, key, message);
  }

  // The node hierarchy, depth first from the roots in file order, with an explicit stack so that a chain of any
  // depth cannot overflow the call stack. glTF requires a forest: a child index that exists, at most one
  // parent per node, and no node reached twice (a cycle, or a root that is also a child), which also bounds
  // the work by the node count (a node listing the same child twice would otherwise double it per level).
  void walk(const std::vector<int>& roots) {
    const size_t n = model_.nodes.size();
    std::vector<int> parent(n, -1);
    for (size_t i = 0; i < n; ++i)
      for (int c : model_.nodes[i].children) {
        const std::string key = indexed("nodes", i) + ".children";
        if (c < 0 || size_t(c) >= n) fail(key, "node " + std::to_string(c) + " does not exist");
        if (parent[size_t(c)] >= 0)
          fail(key, "node " + std::to_string(c) + " is already a child of node " + std::to_string(parent[size_t(c)]) +
                        ": a glTF node has at most one parent");
        parent[size_t(c)] = int(i);
      }
    parent_ = parent;
    world_.assign(n, std::nullopt);
    struct Item {
      int index;
      glm::dmat4 parent;
      std::string from;  // where the index was listed, for messages
    };
    std::vector<bool> seen(n, false);
    std::vector<Item> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, glm::dmat4(1.0), "nodes"});
    while (!stack.empty()) {
      const Item item = std::move(stack.back());
      stack.pop_back();
      if (item.index < 0 || size_t(item.index) >= n)
        fail(item.from, "node " + std::to_string(item.index) + " does not exist");
      if (seen[size_t(item.index)])
        fail(item.from, "node " + std::to_string(item.index) + " is reached twice: the node hierarchy has a cycle");
      seen[size_t(item.index)] = true;
      const std::string key = indexed("nodes", size_t(item.index));
      const tinygltf::Node& node = model_.nodes[size_t(item.index)];
      check_transform_fields(node, key);
      const glm::dmat4 local = node_matrix(node);
      // glTF 2.0 §5.25: a node's matrix is a decomposable affine transform (its last row 0, 0, 0, 1).
      bool finite = true;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) finite &= std::isfinite(local[c][r]);
      if (!finite) fail(key, "the node's transform holds a value that is not a finite number");
      if (local[0][3] != 0.0 || local[1][3] != 0.0 || local[2][3] != 0.0 || local[3][3] != 1.0)
        fail(key + ".matrix", "not an affine transform: its last row must be 0, 0, 0, 1");
      const glm::dmat4 world = item.parent * local;
      world_[size_t(item.index)] = world;
      const glm::mat4 worldf(world);
      if (node.mesh >= 0) add_mesh_instances(size_t(item.index), worldf, key);
      if (node.camera >= 0) add_camera(node, worldf, key);
      const auto ext = node.extensions.find("KHR_lights_punctual");
      if (ext != node.extensions.end() && ext->second.Has("light")) {
        const tinygltf::Value& v = ext->second.Get("light");
        if (!v.IsInt()) fail(key + ".extensions.KHR_lights_punctual.light", "expected a light index");
        add_light(v.GetNumberAsInt(), worldf, key);
      }
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
        stack.push_back({*c, world, key + ".children"});
    }
  }

  // glTF 2.0 §5.25: a matrix of 16 numbers, or a translation (3), rotation (a unit quaternion, 4) and scale (3)
  // (both at once is refused by gltf_json_check: tinygltf drops the second). A shorter array was ignored, and a
  // zero quaternion made every vertex NaN.
  void check_transform_fields(const tinygltf::Node& node, const std::string& key) const {
    const std::pair<const std::vector<double>*, std::pair<const char*, size_t>> fields[] = {
        {&node.matrix, {"matrix", 16}}, {&node.translation, {"translation", 3}},
        {&node.rotation, {"rotation", 4}}, {&node.scale, {"scale", 3}}};
    for (const auto& [v, spec] : fields)
      if (!v->empty() && v->size() != spec.second)
        fail(key + "." + spec.first, "needs " + std::to_string(spec.second) + " numbers, not " + std::to_string(v->size()));
    if (node.rotation.size() == 4) {
      const double q = std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                                 node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
      if (!(q > 0.0) || !std::isfinite(q)) fail(key + ".rotation", "is not a unit quaternion (its length is " +
                                                                        std::to_string(q) + ")");
    }
  }

  // A node's primitives as instances. A skinned or morphed node's meshes are its own, posed (gltf_pose.h) once
  // the whole hierarchy is walked, since its joints may come later: its instances are placed now, in file
  // order, and their meshes filled in by pose().
  void add_mesh_instances(size_t index, const glm::mat4& world, const std::string& key) {
    const tinygltf::Node& node = model_.nodes[index];
    if (size_t(node.mesh) >= model_.meshes.size())
      fail(key + ".mesh", "mesh " + std::to_string(node.mesh) + " does not exist");
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    if (node.skin >= 0 && size_t(node.skin) >= model_.skins.size())
      fail(key + ".skin", "skin " + std::to_string(node.skin) + " does not exist");
    check_morph_counts(node, key);
    if (node.skin >= 0 || !gltf::morph_weights(node, mesh).empty()) {
      posed_.push_back({index, key, out_.instances.size(), world});
      for (const tinygltf::Primitive& prim : mesh.primitives) {
        const int mode = mode_of(prim);
        if (!triangles(mode)) continue;  // pose() says why, as primitive() does
        Instance inst;
        inst.name = !node.name.empty() ? node.name : mesh.name;
        inst.transform = node.skin >= 0 ? glm::mat4(1.0f) : world;  // skinned: the joints place it (glTF §3.7.3.3)
        out_.instances.push_back(inst);
      }
      return;
    }
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const auto converted = primitive(size_t(node.mesh), p);
      if (!converted) continue;
      Instance inst;
      inst.name = !node.name.empty() ? node.name : mesh.name;
      inst.mesh = converted->first;
      inst.material = converted->second;
      inst.transform = world;
      out_.instances.push_back(inst);
    }
  }

  // The scene mesh and material of a primitive, converted on first use; nothing for points and lines.
  std::optional<std::pair<uint32_t, uint32_t>> primitive(size_t m, size_t p) {
    const auto key = std::make_pair(m, p);
    if (auto it = primitives_.find(key); it != primitives_.end()) return it->second;
    const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
    const std::string where = indexed("meshes", m) + "." + indexed("primitives", p);
    const int mode = mode_of(prim);
    std::optional<std::pair<uint32_t, uint32_t>> result;
    if (triangles(mode)) {
      out_.meshes.push_back(convert(prim, mode, where, model_.meshes[m].name));
      result = std::make_pair(uint32_t(out_.meshes.size() - 1), materials_.material(prim.material, where));
    } else {
      skip(mode, where);
    }
    primitives_[key] = result;
    return result;
  }

  // A primitive's mode, TRIANGLES where it gives none.
  static int mode_of(const tinygltf::Primitive& prim) { return prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode; }
  static bool triangles(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
  }
  // Points and lines are skipped with a warning (once per primitive); any other mode is an error.
  void skip(int mode, const std::string& where) {
    if (mode < 0 || mode > 3) fail(where + ".mode", "unknown primitive mode " + std::to_string(mode));
    const std::string w = file_ + ": " + where + ": mode " + std::to_string(mode) + " (points or lines) skipped";
    if (std::find(out_.warnings.begin(), out_.warnings.end(), w) == out_.warnings.end()) out_.warnings.push_back(w);
  }

  // glTF 2.0 §3.7.2.2: every primitive of a mesh has as many morph targets, and weights (the node's, the mesh's)
  // give one per target.
  void check_morph_counts(const tinygltf::Node& node, const std::string& key) const {
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    const std::string m = indexed("meshes", size_t(node.mesh));
    const size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    for (size_t p = 1; p < mesh.primitives.size(); ++p)
      if (mesh.primitives[p].targets.size() != targets)
        fail(m + "." + indexed("primitives", p) + ".targets",
             std::to_string(mesh.primitives[p].targets.size()) + " morph targets where primitive 0 has " +
                 std::to_string(targets));
    const auto count = [&](const std::vector<double>& w, const std::string& where) {
      if (!w.empty() && w.size() != targets)
        fail(where, std::to_string(w.size()) + " weights for " + std::to_string(targets) + " morph targets");
    };
    count(mesh.weights, m + ".weights");
    count(node.weights, key + ".weights");
  }

  // A node whose meshes are posed after the walk: its index, key, first instance and world transform.
  struct Posed {
    size_t node;
    std::string key;
    size_t first_instance;
    glm::mat4 world;
  };

  // A node's world transform, for a joint: as walked, or (a joint outside the scene's hierarchy) composed up its
  // parents, which walk() has checked are unique; a chain longer than the node count is a cycle.
  glm::dmat4 global(int index, const std::string& key) const {
    glm::dmat4 m(1.0);
    for (size_t steps = 0; index >= 0; ++steps) {
      if (steps > model_.nodes.size()) fail(key, "the joint's parents form a cycle");
      if (world_[size_t(index)]) return *world_[size_t(index)] * m;
      check_transform_fields(model_.nodes[size_t(index)], indexed("nodes", size_t(index)));  // not walked
      m = node_matrix(model_.nodes[size_t(index)]) * m;
      index = parent_[size_t(index)];
    }
    return m;
  }

  void pose(const Posed& p) {
    const tinygltf::Node& node = model_.nodes[p.node];
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    const std::vector<double> weights = gltf::morph_weights(node, mesh);
    std::vector<glm::mat4> joints;
    if (node.skin >= 0) {
      const tinygltf::Skin& skin = model_.skins[size_t(node.skin)];
      const std::string key = indexed("skins", size_t(node.skin)) + ".joints";
      std::vector<glm::dmat4> globals;
      for (int j : skin.joints) {
        if (j < 0 || size_t(j) >= model_.nodes.size()) fail(key, "node " + std::to_string(j) + " does not exist");
        globals.push_back(global(j, key));
      }
      joints = gltf::joint_matrices(model_, size_t(node.skin), read_, file_, globals);
    }
    size_t instance = p.first_instance, unweighted = 0;
    for (size_t k = 0; k < mesh.primitives.size(); ++k) {
      const tinygltf::Primitive& prim = mesh.primitives[k];
      const std::string where = indexed("meshes", size_t(node.mesh)) + "." + indexed("primitives", k);
      const int mode = mode_of(prim);
      if (!triangles(mode)) {
        skip(mode, where);
        continue;
      }
      // A skinned mesh is posed in world space under an identity instance, so build_scene() cannot see a
      // mirroring node: its winding is flipped here, by the node's global transform (glTF §3.7.4).
      const bool mirrored = node.skin >= 0 && glm::determinant(glm::mat3(p.world)) < 0.0f;
      Mesh m = convert(prim, mode, where, mesh.name, [&](Mesh& raw) {
        if (!weights.empty()) gltf::apply_morph_targets(prim, weights, read_, quantized_, file_, where, raw);
        if (node.skin >= 0) unweighted += gltf::apply_skin(prim, joints, p.world, read_, file_, where, raw);
      }, mirrored);
      out_.meshes.push_back(std::move(m));
      Instance& inst = out_.instances[instance++];
      inst.mesh = uint32_t(out_.meshes.size() - 1);
      inst.material = materials_.material(prim.material, where);
    }
    if (unweighted)
      out_.warnings.push_back(file_ + ": " + p.key + ": " + std::to_string(unweighted) +
                              " skinned vertices have weights summing to 0: placed by the node's transform");
  }

  // A primitive as a scene mesh; `deform` (the pose of a skinned or morphed node) runs on its positions and
  // normals as read, before they are checked and missing or broken normals computed.
  Mesh convert(const tinygltf::Primitive& prim, int mode, const std::string& where, const std::string& name,
               const std::function<void(Mesh&)>& deform = {}, bool flip = false) {
    auto attribute = [&](const char* semantic) {
      const auto it = prim.attributes.find(semantic);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    const std::string attr = where + ".attributes.";
    Mesh mesh;
    mesh.name = name;
    const int position = attribute("POSITION");
    if (position < 0) fail(where + ".attributes", "no POSITION attribute");
    using Quantized = gltf::AccessorReader::Quantized;
    mesh.positions = read_.vec3(position, attr + "POSITION", quantized_ ? Quantized::position : Quantized::no);
    if (const int n = attribute("NORMAL"); n >= 0) {
      mesh.normals = read_.vec3(n, attr + "NORMAL", quantized_ ? Quantized::normal : Quantized::no);
      if (mesh.normals.size() != mesh.positions.size()) fail(attr + "NORMAL", "count differs from POSITION");
    }
    if (deform) deform(mesh);
    // The set the base-colour texture names (TEXCOORD_0 without one), v turned into GL's t = 1 − v.
    const std::string uv = "TEXCOORD_" + std::to_string(materials_.texcoord_set(prim.material));
    if (const int t = attribute(uv.c_str()); t >= 0) {
      mesh.texcoords = read_.vec2(t, attr + uv, quantized_);
      if (mesh.texcoords.size() != mesh.positions.size()) fail(attr + uv, "count differs from POSITION");
      for (glm::vec2& c : mesh.texcoords) c.y = 1.0f - c.y;
    } else if (uv != "TEXCOORD_0") {
      fail(attr + uv, "missing: the material's base-colour texture reads it");
    } else if (materials_.has_base_texture(prim.material)) {  // exporters write these; drawn, but said
      out_.warnings.push_back(file_ + ": " + attr + uv + ": missing, though the material's base-colour texture "
                              "reads it: the texel at (0, 0) colours the whole primitive");
    }
    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
      indices = read_.indices(prim.indices, where + ".indices");
    } else {
      indices.resize(mesh.positions.size());
      std::iota(indices.begin(), indices.end(), 0u);
    }
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) indices = strip_to_list(indices);
    else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) indices = fan_to_list(indices);
    mesh.indices = std::move(indices);
    if (flip) flip_winding(mesh);  // before normals are computed from the winding
    if (auto problem = mesh_problem(mesh)) fail(where, *problem);
    if (const size_t fixed = repair_normals(mesh))
      out_.warnings.push_back(file_ + ": " + attr + "NORMAL: " + std::to_string(fixed) +
                              " non-finite or zero normals replaced by computed ones");
    return mesh;
  }

  void add_camera(const tinygltf::Node& node, const glm::mat4& world, const std::string& key) {
    if (size_t(node.camera) >= model_.cameras.size())
      fail(key + ".camera", "camera " + std::to_string(node.camera) + " does not exist");
    const tinygltf::Camera& src = model_.cameras[size_t(node.camera)];
    const std::string where = indexed("cameras", size_t(node.camera));
    Camera c;
    c.name = !src.name.empty() ? src.name : node.name;
    c.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
    const glm::vec3 forward(world * glm::vec4(0, 0, -1, 0)), up(world * glm::vec4(0, 1, 0, 0));
    if (!(glm::length(glm::cross(forward, up)) > 0.0f) || !std::isfinite(glm::length(forward) + glm::length(up)))
      fail(key, "the node's transform flattens camera " + std::to_string(node.camera) +
                    ": its view direction and up vector are zero or parallel");
    c.target = c.position + glm::normalize(forward);
    c.up = glm::normalize(up);
    if (src.type == "orthographic") {
      const auto& o = src.orthographic;
      if (!(o.xmag != 0.0 && o.ymag != 0.0 && o.zfar > o.znear && o.znear >= 0.0))
        fail(where + ".orthographic", "needs non-zero xmag and ymag and 0 <= znear < zfar");
      c.projection = Orthographic{float(-o.xmag), float(o.xmag),  float(-o.ymag),
                                  float(o.ymag),  float(o.znear), float(o.zfar)};
    } else {
      const auto& p = src.perspective;
      if (!(p.yfov > 0.0 && p.yfov < glm::pi<double>() && p.znear > 0.0))
        fail(where + ".perspective", "needs 0 < yfov < pi and a positive znear");
      Perspective persp;
      persp.fovy_deg = float(glm::degrees(p.yfov));
      if (p.aspectRatio > 0.0) persp.aspect = float(p.aspectRatio);
      persp.near = float(p.znear);
      // zfar 0 (tinygltf's value when absent) is glTF's infinite projection, taken as far = 1000 znear.
      if (p.zfar != 0.0 && !(p.zfar > p.znear)) fail(where + ".perspective.zfar", "must be greater than znear");
      persp.far = p.zfar > p.znear ? float(p.zfar) : float(1000.0 * p.znear);
      c.projection = persp;
    }
    out_.cameras.push_back(c);
  }

  void add_light(int index, const glm::mat4& world, const std::string& key) {
    const std::string where = key + ".extensions.KHR_lights_punctual.light";
    if (index < 0 || size_t(index) >= model_.lights.size())
      fail(where, "light " + std::to_string(index) + " does not exist");
    const tinygltf::Light& src = model_.lights[size_t(index)];
    Light l;
    l.name = src.name;
    if (src.type == "directional") l.type = LightType::directional;
    else if (src.type == "point") l.type = LightType::point;
    else if (src.type == "spot") l.type = LightType::spot;
    else fail(where, "unknown light type '" + src.type + "'");
    // The light's own values, as KHR_lights_punctual bounds them (tinygltf reads an absent range as 0).
    const std::string own = "extensions.KHR_lights_punctual." + indexed("lights", size_t(index));
    const auto finite_non_negative = [](double v) { return std::isfinite(float(v)) && v >= 0.0; };
    if (!src.color.empty() &&  // absent: white
        (src.color.size() != 3 || !std::all_of(src.color.begin(), src.color.end(), finite_non_negative)))
      fail(own + ".color", "needs three finite components of 0 or more");
    if (!finite_non_negative(src.intensity))
      fail(own + ".intensity", "must be a finite number of 0 or more (candela, or lux for a directional light)");
    if (!finite_non_negative(src.range)) fail(own + ".range", "must be a finite number above 0");
    if (!src.color.empty()) l.color = glm::vec3(glm::make_vec3(src.color.data()));
    l.intensity = float(src.intensity);
    l.range = float(src.range);
    l.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
    const glm::vec3 facing(world * glm::vec4(0, 0, -1, 0));
    if (l.type != LightType::point && !(glm::length(facing) > 0.0f && std::isfinite(glm::length(facing))))
      fail(key, "the node's transform flattens light " + std::to_string(index) + "'s direction to zero");
    l.direction = glm::length(facing) > 0.0f ? glm::normalize(facing) : glm::vec3(0, 0, -1);  // a point: unused
    if (l.type == LightType::spot) {  // KHR_lights_punctual: 0 <= inner < outer <= pi/2
      const double inner = src.spot.innerConeAngle, outer = src.spot.outerConeAngle;
      if (!(inner >= 0.0 && inner < outer && outer <= glm::half_pi<double>() + 1e-9))
        fail(where + ".spot", "innerConeAngle " + std::to_string(inner) + " and outerConeAngle " +
                                  std::to_string(outer) + " must satisfy 0 <= inner < outer <= pi/2");
    }
    l.inner_cone_deg = float(glm::degrees(src.spot.innerConeAngle));
    l.outer_cone_deg = float(glm::degrees(src.spot.outerConeAngle));
    l.shadow = default_shadow_settings(l.type);
    out_.lights.push_back(l);
  }

  const tinygltf::Model& model_;
  std::string file_;
  Scene& out_;
  gltf::AccessorReader read_;
  std::map<std::pair<size_t, size_t>, std::optional<std::pair<uint32_t, uint32_t>>> primitives_;
  gltf::GltfMaterials materials_;
  bool quantized_;                               // the file uses KHR_mesh_quantization
  std::vector<int> parent_;                      // each node's parent (-1: a root), from walk()
  std::vector<std::optional<glm::dmat4>> world_;  // each walked node's world transform
  std::vector<Posed> posed_;                     // skinned or morphed nodes, posed after the walk
};

}  // namespace

Scene import_gltf(const std::filesystem::path& path, const std::string& label) {
  const std::string file = label.empty() ? path.string() : label;
  Scene out;
  DataUriImages data_uri_images;
  const tinygltf::Model model = load_model(path, file, out, data_uri_images);
  out.name = path.stem().string();
  out.objects.push_back(out.name);
  Importer(model, std::move(data_uri_images), file, path.parent_path(), out).run();
  return out;
}

}  // namespace scenes
