// Scenes whose exact hard shadow is known in closed form, for the reference's tests: a square over a floor under
// a directional light, a sphere over a floor under a point light, and a spot over an empty floor.
#pragma once
#include <string>

#include "scenes/scene.h"
#include "scenes/scene_build.h"
#include "scenes/scene_json.h"

namespace testsupport {

inline scenes::Scene scene_from_json(const std::string& json) {
  return scenes::build_scene(scenes::parse_scene_json(json, "test.json"));
}

// A 1 x 1 m square (a plane primitive, facing up) at y = 1 centred over the origin, an 8 x 8 m floor at y = 0, the
// sun travelling along (0.3, -1, 0.2), the camera straight above.
inline const char* kSquareOverFloor = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [8, 8]}},
    {"name": "square", "primitive": {"type": "plane", "size": [1, 1]}, "transform": {"translate": [0, 1, 0]}}
  ],
  "cameras": [{"position": [0, 9, 2], "target": [0, 0, 0]}],
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}]
})";

// A sphere of radius 0.5 centred at (0, 1, 0) (64 segments, 32 rings), an 8 x 8 m floor, a point light at
// (0.4, 3, 0.2) with a 20 m range.
inline const char* kSphereUnderPointLight = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [8, 8]}},
    {"name": "ball", "primitive": {"type": "sphere", "radius": 0.5, "segments": 64, "rings": 32},
     "transform": {"translate": [0, 1, 0]}}
  ],
  "cameras": [{"position": [0, 7, 2], "target": [0, 0, 0]}],
  "lights": [{"type": "point", "position": [0.4, 3, 0.2], "range": 20, "shadow": {"technique": "cube"}}]
})";

// A spot at (0, 3, 0) pointing straight down with a 25° outer cone over an empty 8 x 8 m floor: the lit disc has
// radius 3 · tan 25°.
inline const char* kSpotOverFloor = R"({
  "objects": [{"name": "floor", "primitive": {"type": "plane", "size": [8, 8]}}],
  "cameras": [{"position": [0, 7, 2], "target": [0, 0, 0]}],
  "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "inner_cone": 20,
              "outer_cone": 25, "range": 20}]
})";

}  // namespace testsupport
