// The scene document: what a scene JSON file says, before any mesh is generated or glTF file opened.
// The JSON reader fills it, the JSON writer prints it back (load -> save -> load gives an equal document),
// the built-in scenes are written as documents, and build_scene() (scene_build.h) turns one into a Scene.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/scene.h"

namespace scenes {

// Either a matrix, or translate · rotate · scale with the rotation given as Euler angles in degrees
// (applied about X, then Y, then Z: R = Rz · Ry · Rx) or as a unit quaternion.
struct TransformDesc {
  std::optional<glm::mat4> matrix;
  glm::vec3 translate{0.0f};
  glm::vec3 rotate_deg{0.0f};
  std::optional<glm::quat> quaternion;
  glm::vec3 scale{1.0f};
  bool operator==(const TransformDesc&) const = default;
};

// Built-in primitives. Each is centred on the origin unless said otherwise; +Y is up.
struct PlaneShape {        // XZ plane at y = 0, normal +Y
  glm::vec2 size{10.0f, 10.0f};
  uint32_t segments = 1;   // quads per side
  bool operator==(const PlaneShape&) const = default;
};
struct BoxShape {
  glm::vec3 size{1.0f};
  bool operator==(const BoxShape&) const = default;
};
struct SphereShape {
  float radius = 0.5f;
  uint32_t segments = 32;  // around the Y axis
  uint32_t rings = 16;     // pole to pole
  bool operator==(const SphereShape&) const = default;
};
struct CylinderShape {     // axis along Y
  float radius = 0.5f;
  float height = 1.0f;
  uint32_t segments = 32;
  bool caps = true;
  bool operator==(const CylinderShape&) const = default;
};
struct ConeShape {         // axis along Y, apex at +height/2
  float radius = 0.5f;
  float height = 1.0f;
  uint32_t segments = 32;
  bool cap = true;
  bool operator==(const ConeShape&) const = default;
};
// Room sides, as bits of RoomShape::sides.
enum RoomSide : uint8_t {
  room_floor = 1, room_ceiling = 2, room_neg_x = 4, room_pos_x = 8, room_neg_z = 16, room_pos_z = 32,
};
// A room with thick walls: the interior spans x, z in [-size/2, size/2] and y in [0, size.y] (its floor is at
// y = 0); every side present is a closed slab `wall` thick outside that volume.
struct RoomShape {
  glm::vec3 size{12.0f, 5.0f, 12.0f};
  float wall = 0.5f;
  uint8_t sides = room_floor | room_neg_x | room_pos_x | room_neg_z;
  bool operator==(const RoomShape&) const = default;
};
// A heightfield in the XZ plane, heights from a fixed sum of sines (terrain_height() in primitives.h).
struct TerrainShape {
  glm::vec2 size{20.0f, 20.0f};
  uint32_t resolution = 64;   // quads per side
  float amplitude = 0.5f;     // metres, peak
  float wavelength = 6.0f;    // metres, of the longest wave
  uint32_t seed = 1;
  bool operator==(const TerrainShape&) const = default;
};
using Shape = std::variant<PlaneShape, BoxShape, SphereShape, CylinderShape, ConeShape, RoomShape, TerrainShape>;

// A glTF 2.0 file (.gltf or .glb), its path relative to the scene file.
struct GltfRef {
  std::string path;
  bool import_cameras = true;
  bool import_lights = true;
  bool operator==(const GltfRef&) const = default;
};

// What an object draws: nothing (a pure group), a primitive, a glTF file or a mesh written inline.
using ObjectSource = std::variant<std::monostate, Shape, GltfRef, Mesh>;

// One node of the object hierarchy; children are placed relative to their parent. Shadow flags and the
// material are inherited by children that do not set them.
struct ObjectDesc {
  std::string name;
  ObjectSource source;
  TransformDesc transform;
  std::optional<std::string> material;   // name in SceneDesc::materials; for glTF, overrides the file's
  std::optional<bool> casts_shadows;
  std::optional<bool> receives_shadows;
  std::vector<ObjectDesc> children;
  bool operator==(const ObjectDesc&) const = default;
};

struct SceneDesc {
  std::string name;
  std::string description;
  std::vector<Material> materials;   // textures as written (relative to the scene file)
  std::vector<ObjectDesc> objects;
  std::vector<Camera> cameras;
  std::vector<Light> lights;         // directions as written; range 0: reach the whole scene
  Look look;                         // exposure, tone map and background
  bool operator==(const SceneDesc&) const = default;
};

// Primitive names (`plane`, `box`, ...; index = Shape alternative) and room side names (bit i = 1 << i).
std::span<const NamedEntry> primitive_names();
std::span<const NamedEntry> room_side_names();
std::string_view shape_name(const Shape& shape);

// The matrix of a transform: the matrix itself, or T · R · S.
glm::mat4 transform_matrix(const TransformDesc& t);

// A value that breaks a rule: the key (relative to the camera or light, empty for the whole of it) and why.
struct Problem {
  std::string key;
  std::string message;
};
// Checks shared by the JSON reader and build_scene(): a camera needs distinct position and target, an up vector
// not parallel to the view, 0 < fovy < 180 and 0 < near < far (perspective) or non-empty bounds (orthographic);
// a light needs a non-zero direction, 0 <= inner_cone <= outer_cone < 90, range >= 0 and a technique that can
// serve its type.
std::optional<Problem> camera_problem(const Camera& camera);
std::optional<Problem> light_problem(const Light& light);

}  // namespace scenes
