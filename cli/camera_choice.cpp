// Camera choice for render (see camera_choice.h).
#include "cli/camera_choice.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cli/cli_common.h"
#include "scenes/camera_math.h"
#include "scenes/scene_queries.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// --camera orbit:AZ,EL[,DIST]: azimuth (from +Z towards +X) and elevation in degrees, distance in metres (0: framed).
glm::vec3 parse_orbit(const std::string& spec) {
  const std::string body = spec.substr(6);
  std::vector<float> v;
  size_t start = 0;
  while (start <= body.size() && v.size() < 4) {
    const size_t end = std::min(body.find(',', start), body.size());
    const std::string part = body.substr(start, end - start);
    size_t used = 0;
    float x = 0;
    try {
      x = std::stof(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (part.empty() || used != part.size() || !std::isfinite(x))
      throw CliError("--camera", "expected orbit:AZ,EL[,DIST] with numbers, got '" + spec + "'");
    v.push_back(x);
    start = end + 1;
  }
  if (v.size() < 2 || v.size() > 3) throw CliError("--camera", "expected orbit:AZ,EL[,DIST], got '" + spec + "'");
  if (!(v[1] >= -89.0f && v[1] <= 89.0f)) throw CliError("--camera", "orbit elevation must be within -89..89 degrees");
  if (v.size() == 3 && !(v[2] > 0.0f)) throw CliError("--camera", "orbit distance must be above 0");
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0f};
}

// The camera --camera picks (adding an orbit camera to the scene), as an index into scene.cameras.
size_t choose_camera(scenes::Scene& scene, const std::string& spec) {
  if (spec.empty()) return 0;
  if (spec.rfind("orbit:", 0) == 0) {
    const glm::vec3 o = parse_orbit(spec);
    // Around what casts shadows but a staged ground, framed like the default camera.
    scenes::Aabb box;
    for (size_t i = 0; i < scene.instances.size(); ++i)
      if (scene.instances[i].casts_shadows && scene.instances[i].object != scene.staged_ground)
        box.extend(scenes::instance_bounds(scene, i));
    if (box.empty()) box = scenes::scene_bounds(scene);
    scenes::Camera c = scenes::frame_camera(box, "orbit");
    const float framed = glm::length(c.position - c.target);
    const float distance = o.z > 0.0f ? o.z : framed;
    const float az = glm::radians(o.x), el = glm::radians(o.y);
    c.position = c.target + distance * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    if (auto* p = std::get_if<scenes::Perspective>(&c.projection)) {
      const float radius = 0.5f * glm::length(scenes::scene_bounds(scene).size());
      p->near = std::max(1e-3f * distance, distance - 1.5f * std::max(radius, 1e-3f));
      p->far = distance + 1.5f * std::max(radius, 1e-3f);
    }
    scene.cameras.push_back(c);
    return scene.cameras.size() - 1;
  }
  bool digits = !spec.empty() && spec.size() < 10;
  for (char ch : spec) digits &= std::isdigit(static_cast<unsigned char>(ch)) != 0;
  if (digits) {
    const size_t i = std::stoul(spec);
    if (i >= scene.cameras.size())
      throw CliError("--camera", "camera " + spec + " does not exist (the scene has " +
                                     std::to_string(scene.cameras.size()) + ")");
    return i;
  }
  std::string names;
  for (size_t i = 0; i < scene.cameras.size(); ++i) {
    if (scene.cameras[i].name == spec) return i;
    names += (names.empty() ? "" : ", ") + (scene.cameras[i].name.empty() ? std::to_string(i) : scene.cameras[i].name);
  }
  throw CliError("--camera", "no camera named '" + spec + "' (cameras: " + names + "; or an index, or orbit:AZ,EL)");
}

SHADOWLAB_ISA_END
}  // namespace cli
