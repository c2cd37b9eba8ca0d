// A bare model made ready to look at (see stage.h).
#include "scenes/stage.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scenes/camera_math.h"
#include "scenes/scene_build.h"
#include "scenes/scene_desc.h"
#include "scenes/scene_error.h"
#include "scenes/scene_queries.h"
#include "scenes/shadow_settings.h"

namespace scenes {

glm::vec3 sun_direction(float az_deg, float el_deg) {
  const float az = glm::radians(az_deg), el = glm::radians(el_deg);
  return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

namespace {

// How far from the box's vertical axis (the larger of the x and z distances) its shadow on the plane under it
// reaches, cast along `direction` (the way the light travels, downwards), its own footprint included.
float shadow_reach(const Aabb& b, glm::vec3 direction) {
  const glm::vec3 centre = b.center();
  float reach = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    const glm::vec3 on_ground = direction.y < 0.0f ? p + direction * ((p.y - b.min.y) / -direction.y) : p;
    reach = std::max({reach, std::abs(on_ground.x - centre.x), std::abs(on_ground.z - centre.z)});
  }
  return std::isfinite(reach) ? reach : 0.0f;
}

}  // namespace

StagedScene load_model_staged(const std::filesystem::path& path, const StageOptions& options) {
  SceneDesc desc;
  desc.name = path.stem().string();
  ObjectDesc model;
  model.name = desc.name;
  model.source = GltfRef{path.filename().string()};
  // Rotations about X taking the model's up to +Y: +Z by −90°, −Z by +90°, −Y by 180° (a turn, not a mirror).
  switch (options.up) {
    case StageOptions::Up::y: break;
    case StageOptions::Up::z: model.transform.rotate_deg = glm::vec3(-90.0f, 0.0f, 0.0f); break;
    case StageOptions::Up::minus_y: model.transform.rotate_deg = glm::vec3(180.0f, 0.0f, 0.0f); break;
    case StageOptions::Up::minus_z: model.transform.rotate_deg = glm::vec3(90.0f, 0.0f, 0.0f); break;
  }
  desc.objects.push_back(model);
  BuildContext context{path.parent_path(), path.string()};
  context.wraps_model = true;
  if (options.sun) {
    const glm::vec2 s = *options.sun;
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || s.y <= 0.0f || s.y > 90.0f)
      throw SceneError("sun", "", "expected AZ,EL with an elevation above 0 and at most 90 degrees");
  }

  // The model alone first: its own lights and cameras, and its bounds.
  BuildContext probe_context = context;
  probe_context.default_camera = probe_context.default_light = false;
  const Scene probe = build_scene(desc, probe_context);
  const Aabb bounds = scene_bounds(probe);
  StagedScene out;
  const std::string file = path.filename().string();
  float ground_side = 0.0f;  // the staged ground's side, when one is added
  // The camera the frame will use first: the file's, or one framing the model.
  glm::vec3 eye = bounds.empty() ? glm::vec3(0.0f, 0.0f, 1.0f) : frame_camera(bounds).position;
  if (!probe.cameras.empty()) eye = probe.cameras[0].position;
  if (probe.lights.empty()) {
    // By default the sun stands kStageSunAzimuth to the side of the camera's azimuth (seen from the model), so
    // the shadow falls sideways across the ground the camera sees instead of hiding behind the model.
    const glm::vec3 view = eye - (bounds.empty() ? glm::vec3(0.0f) : bounds.center());
    const float camera_az = glm::degrees(std::atan2(view.x, view.z));
    const float az = options.sun ? options.sun->x : std::remainder(camera_az + kStageSunAzimuth, 360.0f);
    const float el = options.sun ? options.sun->y : kStageSunElevation;
    Light sun;
    sun.name = "sun";
    sun.intensity = 100000.0f;  // lux: a clear-day sun
    sun.direction = sun_direction(az, el);
    sun.shadow = default_shadow_settings(LightType::directional);
    desc.lights.push_back(sun);
    char line[256];
    std::snprintf(line, sizeof line, "%s has no lights: added a sun at azimuth %.0f, elevation %.0f degrees (--sun AZ,EL)",
                  file.c_str(), double(az), double(el));
    out.notes.push_back(line);
    if (options.ground && !bounds.empty()) {
      const glm::vec3 size = bounds.size(), centre = bounds.center();
      // Three times the model's footprint, at any scale (a floor of 1 mm made a 1e-6 m model a speck on a
      // plane that the camera then framed); a model with no footprint (all in one vertical line) has its height.
      float side = 3.0f * std::max(size.x, size.z);
      if (!(side > 0.0f)) side = 3.0f * size.y;
      // Wider where the sun's shadow of the model's box reaches beyond that (a tall, narrow model such as the
      // antique camera on its tripod: the head's shadow ran off the ground's corner), with a tenth to spare.
      side = std::max(side, 2.2f * shadow_reach(bounds, sun.direction));
      ground_side = side;
      ObjectDesc ground;
      ground.name = "ground";
      ground.source = Shape{PlaneShape{glm::vec2(side), 1}};
      ground.transform.translate = glm::vec3(centre.x, bounds.min.y, centre.z);  // the model stands on it
      // A mid-grey matte ground (albedo 0.5, as concrete): white would outshine the model under the sun.
      Material matte;
      matte.name = "stage ground";
      matte.base_color = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
      matte.specular_strength = 0.05f;
      desc.materials.push_back(matte);
      ground.material = matte.name;
      desc.objects.push_back(ground);
      std::snprintf(line, sizeof line, "added a %.3g m ground plane at y = %.3g under it (--no-ground)", double(side),
                    double(bounds.min.y));
      out.notes.push_back(line);
    }
  }
  if (probe.cameras.empty() && !bounds.empty()) {
    Camera c = frame_camera(bounds, "framed");
    // Far enough for the ground around the model (up to about 2.2 model sizes from its centre, or its corners
    // where the sun's shadow made it wider: half its diagonal, 0.71 of its side).
    if (auto* p = std::get_if<Perspective>(&c.projection)) {
      const double radius = std::max(0.5 * glm::length(glm::dvec3(bounds.size())), 1e-12);  // as frame_camera
      const double reach = std::max(5.0 * radius, 0.75 * double(ground_side));
      p->far = float(std::min(double(glm::length(glm::dvec3(c.position - c.target))) + reach,
                              double(std::numeric_limits<float>::max())));
    }
    desc.cameras.push_back(c);
    if (!options.camera_chosen)
      out.notes.push_back(file + " has no camera: added one framing the model (--camera orbit:AZ,EL)");
  }
  out.scene = build_scene(desc, context);
  if (desc.objects.size() == 2 && out.scene.objects.size() == 2) out.scene.staged_ground = 1;  // model, ground
  return out;
}

void ground_receives_only(Scene& scene) {
  if (!scene.staged_ground) return;
  for (Instance& inst : scene.instances)
    if (inst.object == *scene.staged_ground) inst.casts_shadows = false;
}

}  // namespace scenes
