// A glTF mesh's default pose: morph targets at their default weights, then the skin (see gltf_pose.h).
#include "scenes/gltf_pose.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

#include "scenes/scene_error.h"

namespace scenes::gltf {
namespace {

// The attribute's accessor index, or -1.
int attribute(const std::map<std::string, int>& attributes, const std::string& semantic) {
  const auto it = attributes.find(semantic);
  return it == attributes.end() ? -1 : it->second;
}

}  // namespace

std::vector<double> morph_weights(const tinygltf::Node& node, const tinygltf::Mesh& mesh) {
  size_t targets = 0;
  for (const tinygltf::Primitive& p : mesh.primitives) targets = std::max(targets, p.targets.size());
  std::vector<double> w = !node.weights.empty() ? node.weights : mesh.weights;
  w.resize(targets, 0.0);
  if (std::all_of(w.begin(), w.end(), [](double v) { return v == 0.0; })) w.clear();
  return w;
}

void apply_morph_targets(const tinygltf::Primitive& prim, const std::vector<double>& weights,
                         const AccessorReader& read, bool quantized, const std::string& file,
                         const std::string& where, Mesh& mesh) {
  for (size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t) {
    const float w = float(weights[t]);
    if (!std::isfinite(w)) throw SceneError(file, where, "morph weight " + std::to_string(t) + " is not a finite number");
    if (w == 0.0f) continue;
    const std::string key = where + ".targets[" + std::to_string(t) + "].";
    const auto add = [&](const char* semantic, std::vector<glm::vec3>& values) {
      const int a = attribute(prim.targets[t], semantic);
      if (a < 0 || values.empty()) return;
      using Quantized = AccessorReader::Quantized;
      const Quantized q = !quantized ? Quantized::no
                          : std::string(semantic) == "POSITION" ? Quantized::target_position : Quantized::normal;
      const std::vector<glm::vec3> d = read.vec3(a, key + semantic, q);
      if (d.size() != values.size())
        throw SceneError(file, key + semantic, "count " + std::to_string(d.size()) + " differs from POSITION's " +
                                                   std::to_string(values.size()));
      for (size_t i = 0; i < values.size(); ++i) values[i] += w * d[i];
    };
    add("POSITION", mesh.positions);
    add("NORMAL", mesh.normals);
  }
}

std::vector<glm::mat4> joint_matrices(const tinygltf::Model& model, size_t skin, const AccessorReader& read,
                                      const std::string& file, const std::vector<glm::dmat4>& globals) {
  const tinygltf::Skin& s = model.skins[skin];
  const std::string key = "skins[" + std::to_string(skin) + "]";
  std::vector<glm::mat4> inverse_bind(s.joints.size(), glm::mat4(1.0f));
  if (s.inverseBindMatrices >= 0) {
    inverse_bind = read.mat4(s.inverseBindMatrices, key + ".inverseBindMatrices");
    if (inverse_bind.size() < s.joints.size())
      throw SceneError(file, key + ".inverseBindMatrices",
                       std::to_string(inverse_bind.size()) + " matrices for " + std::to_string(s.joints.size()) +
                           " joints");
  }
  const auto finite = [](const auto& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(m[c][r])) return false;
    return true;
  };
  std::vector<glm::mat4> out(s.joints.size());
  for (size_t j = 0; j < s.joints.size(); ++j) {
    if (!finite(inverse_bind[j]))
      throw SceneError(file, key + ".inverseBindMatrices", "matrix " + std::to_string(j) + " holds a value that is not a finite number");
    if (!finite(globals[j]))
      throw SceneError(file, key + ".joints", "node " + std::to_string(s.joints[j]) + "'s transform holds a value that is not a finite number");
    out[j] = glm::mat4(globals[j] * glm::dmat4(inverse_bind[j]));
    if (!finite(out[j]))
      throw SceneError(file, key + ".joints", "joint " + std::to_string(j) + "'s matrix overflows a 32-bit float");
  }
  return out;
}

size_t apply_skin(const tinygltf::Primitive& prim, const std::vector<glm::mat4>& joints, const glm::mat4& unskinned,
                  const AccessorReader& read, const std::string& file, const std::string& where, Mesh& mesh) {
  const std::string attr = where + ".attributes.";
  const size_t n = mesh.positions.size();
  std::vector<glm::mat4> skin(n, glm::mat4(0.0f));
  std::vector<float> total(n, 0.0f);
  size_t sets = 0;
  for (;; ++sets) {
    const std::string js = "JOINTS_" + std::to_string(sets), ws = "WEIGHTS_" + std::to_string(sets);
    const int ja = attribute(prim.attributes, js), wa = attribute(prim.attributes, ws);
    if (ja < 0 && wa < 0) break;
    if (ja < 0 || wa < 0)
      throw SceneError(file, attr + (ja < 0 ? js : ws), "missing: the primitive has " + (ja < 0 ? ws : js));
    const std::vector<glm::uvec4> index = read.joints(ja, attr + js);
    const std::vector<glm::vec4> weight = read.weights(wa, attr + ws);
    for (const auto& [size, name] : {std::pair{index.size(), js}, std::pair{weight.size(), ws}})
      if (size != n) throw SceneError(file, attr + name, "count differs from POSITION");
    for (size_t v = 0; v < n; ++v)
      for (int c = 0; c < 4; ++c) {
        const float w = weight[v][c];
        if (!std::isfinite(w) || w < 0.0f)
          throw SceneError(file, attr + ws, "vertex " + std::to_string(v) + " has a weight that is not a finite number of 0 or more");
        if (w == 0.0f) continue;
        if (index[v][c] >= joints.size())
          throw SceneError(file, attr + js, "vertex " + std::to_string(v) + " names joint " +
                                                std::to_string(index[v][c]) + " of a skin with " +
                                                std::to_string(joints.size()));
        skin[v] += w * joints[index[v][c]];
        total[v] += w;
      }
  }
  if (sets == 0) throw SceneError(file, attr + "JOINTS_0", "missing: the node has a skin");
  // glTF numbers attribute sets from 0 without gaps: a later set after the missing one would be ignored.
  for (const auto& attribute : prim.attributes)
    for (const char* prefix : {"JOINTS_", "WEIGHTS_"})
      if (const std::string& semantic = attribute.first; semantic.rfind(prefix, 0) == 0) {
        const std::string n = semantic.substr(std::strlen(prefix));
        if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos || std::stoul(n) >= sets)
          throw SceneError(file, attr + semantic, std::string("follows a gap: the sets of ") + prefix +
                                                      "n are numbered from 0 without one (the last read is " +
                                                      std::to_string(sets - 1) + ")");
      }
  size_t unweighted = 0;
  for (size_t v = 0; v < n; ++v) {
    glm::mat4 m = unskinned;
    if (total[v] > 0.0f) m = skin[v] / total[v];
    else ++unweighted;
    mesh.positions[v] = glm::vec3(m * glm::vec4(mesh.positions[v], 1.0f));
    if (!mesh.normals.empty()) mesh.normals[v] = glm::transpose(glm::inverse(glm::mat3(m))) * mesh.normals[v];
  }
  return unweighted;
}

}  // namespace scenes::gltf
