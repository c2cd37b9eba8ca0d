// The pose a glTF mesh is drawn in when nothing animates it (glTF 2.0 §3.7.2.2 and §3.7.3): its morph targets
// added at their default weights (the node's `weights`, else the mesh's), then its skin applied with each
// joint's current node transform, vertex by vertex, as a viewer shows the file before any animation plays.
// Internal to the scenes module: only gltf_import.cpp includes it.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_accessors.h"
#include "scenes/scene.h"

namespace scenes::gltf {

// The morph weights a node's mesh is drawn with: the node's `weights` where it has them, else the mesh's
// (missing ones are 0). Empty when every weight is 0 or the mesh has no targets.
std::vector<double> morph_weights(const tinygltf::Node& node, const tinygltf::Mesh& mesh);

// Adds each target's POSITION (and NORMAL, where the mesh has normals) displacement times its weight to
// `mesh`. `where` names the primitive ("meshes[0].primitives[1]"); errors are SceneErrors on `file`.
void apply_morph_targets(const tinygltf::Primitive& prim, const std::vector<double>& weights,
                         const AccessorReader& read, bool quantized, const std::string& file,
                         const std::string& where, Mesh& mesh);

// A skin's joint matrices: globalTransform(joint) · inverseBindMatrix(joint), in the skin's joint order
// (identity bind matrices where the skin gives none, as glTF allows; tinygltf 2.8, the loader, refuses a skin
// without them before this runs). `globals` holds each joint node's world transform, in the
// same order (the caller has checked the joints exist).
std::vector<glm::mat4> joint_matrices(const tinygltf::Model& model, size_t skin, const AccessorReader& read,
                                      const std::string& file, const std::vector<glm::dmat4>& globals);

// Moves every vertex of `mesh` (positions, and normals by the inverse transpose) by the weighted sum of its
// joints' matrices (JOINTS_n / WEIGHTS_n, every set the primitive has): the result is in world space, the
// skinned node's own transform ignored as glTF requires. Weights that do not sum to 1 are divided by their sum
// (as three.js and Blender's importer do); a vertex whose weights sum to 0 is placed by `unskinned` (the node's
// world transform), and apply_skin returns how many were, for the caller's warning.
size_t apply_skin(const tinygltf::Primitive& prim, const std::vector<glm::mat4>& joints, const glm::mat4& unskinned,
                  const AccessorReader& read, const std::string& file, const std::string& where, Mesh& mesh);

}  // namespace scenes::gltf
