// Staging a bare glTF model so that its first render shows what shadowlab is for: a model file with no lights
// gets a sun and, under its bounds, a ground plane to catch the shadow; a model with no camera gets one that
// frames the model (not the ground). What was added is returned as notes for the user. A file's own lights and
// cameras are kept untouched.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "scenes/scene.h"

namespace scenes {

struct StageOptions {
  // A ground plane under a model that has no lights: three times its footprint, or wider where the sun's shadow of
  // its box reaches farther (a tenth to spare). It casts, as a floor is drawn into the maps: filtered maps
  // (esm, vsm, evsm) need their receivers in the map, or every shadow erodes by the blur where the map holds
  // only the far plane (projective shadows want it otherwise: ground_receives_only).
  bool ground = true;
  // Azimuth (from +Z towards +X) and elevation, degrees; default: kStageSunAzimuth degrees round from the
  // camera's azimuth, kStageSunElevation up.
  std::optional<glm::vec2> sun;
  // The model's up axis, rotated to +Y: +Y (as glTF specifies), +Z (CAD and Blender exports without the
  // conversion), −Y (files authored in Vulkan's y-down clip convention), −Z.
  enum class Up : uint8_t { y, z, minus_y, minus_z };
  Up up = Up::y;
  bool camera_chosen = false;        // the caller picks its own camera: the framing camera is added unannounced
};

struct StagedScene {
  Scene scene;
  std::vector<std::string> notes;    // one sentence each: what was added and how to change it
};

// The default sun: its azimuth relative to the camera's, and its elevation, degrees.
inline constexpr float kStageSunAzimuth = 105.0f, kStageSunElevation = 50.0f;

// Loads `path` (.gltf or .glb) as load_scene() does, then stages it as described above. Throws SceneError
// (and for a sun below the horizon or at the zenith's exact opposite, SceneError on "sun").
StagedScene load_model_staged(const std::filesystem::path& path, const StageOptions& options);

// The staged ground of `scene` (Scene::staged_ground), if it has one, made to receive only: projective shadows
// want that, since their casters darken everything beyond them and the article's ground casts nothing.
void ground_receives_only(Scene& scene);

// The direction a sun at azimuth `az` and elevation `el` (degrees) shines along (unit, pointing down for el > 0).
glm::vec3 sun_direction(float az_deg, float el_deg);

}  // namespace scenes
