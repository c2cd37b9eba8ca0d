// Turning a scene document into a Scene: primitives generated, glTF files imported, transforms composed down
// the object hierarchy, mirrored instances given flipped meshes, lights normalised; and load_scene(), the one
// call that reads any scene file (JSON, .gltf or .glb).
#pragma once
#include <filesystem>
#include <string>

#include "scenes/scene.h"
#include "scenes/scene_desc.h"

namespace scenes {

// Where a document came from: relative paths (glTF files, textures) are resolved against `base_dir`, and `file`
// labels errors (a path, or a built-in scene's name).
struct BuildContext {
  std::filesystem::path base_dir;
  std::string file;
  bool default_camera = true;  // add frame_camera() when the scene has no camera (below)
  bool default_light = true;   // add the default sun when the scene has no light (below)
  // The document only wraps one glTF file (load_scene, the stage): its "objects…" keys are not in any file the
  // user wrote, so errors name the file alone.
  bool wraps_model = false;
};

// Builds a scene. Beyond what the document says:
// - identical primitives share one mesh; a glTF file referenced twice is read once;
// - instances whose transform mirrors (determinant < 0) use a copy of their mesh with flipped winding, named
//   after it with " (mirrored)" appended;
// - light directions are normalised; a range of 0 becomes the distance to the farthest corner of the scene;
// - no camera: frame_camera() of the scene's bounds is added; no light: a directional light towards
//   (0.5, 2, 2) with default shadow settings is added;
// - every instance belongs to its top-level object (Scene::objects holds their names, or "object N").
// Throws SceneError (file: key path: what) for a missing glTF file, an invalid primitive, mesh, camera or
// light, an unknown material, or a scene with no triangles at all.
Scene build_scene(const SceneDesc& desc, const BuildContext& context = {});

// Loads a scene file: `.gltf` / `.glb` (case-insensitive) become a scene of that one model (its cameras and
// lights, or the defaults above); anything else is read as a scene JSON document.
Scene load_scene(const std::filesystem::path& path);

}  // namespace scenes
