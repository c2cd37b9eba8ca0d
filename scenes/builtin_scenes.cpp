// The registry of built-in scenes and the small constructors their definitions share (see builtin_scenes.h).
#include "scenes/builtin_scenes.h"

#include <array>

#include "scenes/builtin_parts.h"
#include "scenes/scene_build.h"
#include "scenes/scene_error.h"

namespace scenes {
namespace {

constexpr std::array kBuiltins = {
    BuiltinInfo{"tutorial", "the classic shadow-mapping tutorial room: thick walls, floor, a cylinder and a sphere, "
                            "sun towards (0.5, 2, 2)", false},
    BuiltinInfo{"tutorial-spot", "the tutorial room lit by a spot light from (5, 20, 20)", false},
    BuiltinInfo{"pyramid", "a hemispherical light under the ceiling of a closed room, facing down (pyramid map)",
                false},
    BuiltinInfo{"paraboloid", "a point light with pillars, spheres and boxes all around it (dual paraboloid)", false},
    BuiltinInfo{"projective", "five figures walking on uneven terrain, each casting its own projective shadow "
                              "(animated: time)", true},
    BuiltinInfo{"duel", "a distant tree with the low sun behind it casting a long shadow towards the viewer", false},
};

}  // namespace

std::span<const BuiltinInfo> list_builtin_scenes() { return kBuiltins; }

bool is_builtin_scene(std::string_view name) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.name == name) return true;
  return false;
}

SceneDesc builtin_scene_desc(std::string_view name, const BuiltinParams& params) {
  SceneDesc d;
  if (name == "tutorial") d = builtin::tutorial(false);
  else if (name == "tutorial-spot") d = builtin::tutorial(true);
  else if (name == "pyramid") d = builtin::pyramid();
  else if (name == "paraboloid") d = builtin::paraboloid();
  else if (name == "projective") {
    if (params.figures < 0 || params.figures > 10000)
      throw SceneError(std::string(name), "figures", "must be between 0 and 10000");
    d = builtin::projective(params.time, params.figures);
  }
  else if (name == "duel") d = builtin::duel();
  else {
    std::string known;
    for (const BuiltinInfo& b : kBuiltins) {
      if (!known.empty()) known += ", ";
      known += b.name;
    }
    throw SceneError(std::string(name), "", "unknown built-in scene (known: " + known + ")");
  }
  for (const BuiltinInfo& b : kBuiltins)
    if (b.name == name) d.description = std::string(b.description);
  d.name = std::string(name);
  return d;
}

Scene builtin_scene(std::string_view name, const BuiltinParams& params) {
  return build_scene(builtin_scene_desc(name, params), BuildContext{{}, std::string(name)});
}

namespace builtin {

Material material(std::string name, glm::vec3 color, float specular_strength, float shininess) {
  Material m;
  m.name = std::move(name);
  m.base_color = glm::vec4(color, 1.0f);
  m.specular_strength = specular_strength;
  m.shininess = shininess;
  return m;
}

ObjectDesc object(std::string name, Shape shape, glm::vec3 translate, std::string material, glm::vec3 rotate_deg) {
  ObjectDesc o;
  o.name = std::move(name);
  o.source = std::move(shape);
  o.transform.translate = translate;
  o.transform.rotate_deg = rotate_deg;
  o.material = std::move(material);
  return o;
}

Camera camera(std::string name, glm::vec3 position, glm::vec3 target, float fovy_deg, float near, float far) {
  Camera c;
  c.name = std::move(name);
  c.position = position;
  c.target = target;
  c.projection = Perspective{fovy_deg, std::nullopt, near, far};
  return c;
}

Light light(std::string name, LightType type, ShadowTechnique technique) {
  Light l;
  l.name = std::move(name);
  l.type = type;
  l.shadow = default_shadow_settings(type);
  l.shadow.technique = technique;
  l.shadow.map_size = default_map_size(technique);
  l.shadow.depth_format = default_depth_format(technique);
  return l;
}

}  // namespace builtin
}  // namespace scenes
