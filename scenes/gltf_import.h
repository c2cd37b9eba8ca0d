// glTF 2.0 import (through tinygltf): the default scene's node hierarchy flattened into meshes and instances,
// with materials (base colour factor, texture path or embedded image), cameras and KHR_lights_punctual lights.
#pragma once
#include <filesystem>
#include <string>

#include "scenes/scene.h"

namespace scenes {

// Reads a .gltf or .glb file (recognised by its "glTF" magic, not its extension). `label` names the file in
// errors and warnings (default: the path as given). What it does:
// - nodes: matrix or TRS, composed down the hierarchy of the default scene (or scene 0, or every root node);
// - primitives: TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN (points and lines are skipped with a warning),
//   indexed or not, each one Mesh shared by every node that instances it;
// - normals: computed (area-weighted) when missing, non-finite or zero ones replaced (with a warning);
// - skinned and morphed meshes: the default pose (gltf_pose.h: morph targets at their default weights, joints at
//   their node transforms; a skinned node's own transform ignored), one mesh per such node; no animation;
// - KHR_mesh_quantization: integer attributes, normalized or not, where the file uses the extension;
// - materials: baseColorFactor, the base-colour image (its path, relative to the file; or, for an image in a
//   buffer view or a data: URI, its encoded bytes in Material::embedded_texture), doubleSided; specular
//   strength 0.3·(1 − roughness), shininess 2/roughness⁴ − 2 clamped to [1, 512];
// - cameras: position, target (one metre along −Z) and up from the node; a missing zfar becomes 1000·znear;
// - lights: direction −Z of the node, spot cone half-angles in degrees, default shadow settings per type.
// Every instance belongs to object 0, named after the file. Winding is as stored: build_scene() (and so
// load_scene()) is what flips mirrored instances; only a skinned mesh under a mirroring node, posed in world
// space, is flipped here. Throws SceneError on any problem; nothing partial.
Scene import_gltf(const std::filesystem::path& path, const std::string& label = {});

}  // namespace scenes
