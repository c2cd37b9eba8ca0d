// The built-in scenes: procedural documents that need no files, each with a camera and lights whose shadow
// settings suit the technique it shows. Listed by list_builtin_scenes() for `shadowlab list`.
#pragma once
#include <span>
#include <string_view>

#include "scenes/scene.h"
#include "scenes/scene_desc.h"

namespace scenes {

// Parameters of a built-in scene; only animated scenes look at `time`.
struct BuiltinParams {
  double time = 0.0;  // seconds
  int figures = 5;    // `projective`: walking figures (casters), 0..10000; the first five walk as by default, more
                      // than five walk small circles on a grid (benchmarks)
};

struct BuiltinInfo {
  std::string_view name;
  std::string_view description;  // one line
  bool animated = false;         // depends on BuiltinParams::time
};

std::span<const BuiltinInfo> list_builtin_scenes();
bool is_builtin_scene(std::string_view name);

// The scene as a document (it can be saved as JSON and edited) and built. An unknown name throws SceneError
// `NAME: unknown built-in scene (known: tutorial, ...)`.
SceneDesc builtin_scene_desc(std::string_view name, const BuiltinParams& params = {});
Scene builtin_scene(std::string_view name, const BuiltinParams& params = {});

}  // namespace scenes
