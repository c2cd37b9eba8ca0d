// The built-in `duel` scene: a procedural tree (trunk, two cone crowns, a sphere on top) sixty metres away with
// a low sun behind it, so its long shadow runs towards the viewer: the light and the camera look at each other
// ("duelling frusta"), the case where a classic map wastes resolution far from the eye.
#include <string>

#include "scenes/builtin_parts.h"

namespace scenes::builtin {
namespace {

ObjectDesc tree(glm::vec3 at) {
  ObjectDesc t;
  t.name = "tree";
  t.transform.translate = at;
  t.children.push_back(object("trunk", CylinderShape{0.4f, 5.0f, 24, true}, {0.0f, 2.5f, 0.0f}, "bark"));
  t.children.push_back(object("lower crown", ConeShape{3.0f, 5.0f, 32, true}, {0.0f, 6.5f, 0.0f}, "leaves"));
  t.children.push_back(object("upper crown", ConeShape{2.3f, 4.0f, 32, true}, {0.0f, 9.5f, 0.0f}, "leaves"));
  t.children.push_back(object("top", SphereShape{1.0f, 24, 12}, {0.0f, 12.0f, 0.0f}, "leaves"));
  return t;
}

}  // namespace

SceneDesc duel() {
  SceneDesc d;
  d.materials = {material("ground", {0.55f, 0.62f, 0.40f}, 0.05f, 2.0f), material("bark", {0.40f, 0.28f, 0.18f}),
                 material("leaves", {0.20f, 0.50f, 0.22f}), material("rock", {0.55f, 0.55f, 0.52f})};
  d.objects.push_back(object("ground", BoxShape{{240.0f, 0.5f, 240.0f}}, {0.0f, -0.25f, -50.0f}, "ground"));
  d.objects.push_back(tree({0.0f, 0.0f, -60.0f}));
  // Rocks near the viewer, for the shadow to fall on where the map's texels are largest.
  const glm::vec3 rocks[] = {{-1.5f, 0.0f, -6.0f}, {1.2f, 0.0f, -9.0f}, {-0.5f, 0.0f, -13.0f}};
  int k = 0;
  for (const glm::vec3& at : rocks) {
    ObjectDesc r = object("rock " + std::to_string(k), SphereShape{0.6f, 24, 12}, at, "rock",
                          {0.0f, 30.0f * float(k), 0.0f});
    r.transform.scale = {1.0f, 0.5f, 0.8f};
    d.objects.push_back(r);
    ++k;
  }
  d.cameras.push_back(camera("main", {1.5f, 1.7f, 6.0f}, {0.0f, 4.0f, -60.0f}, 40.0f, 0.3f, 300.0f));

  Light sun = light("sun", LightType::directional, ShadowTechnique::shadowmap);
  sun.intensity = 30000.0f;  // lux: a low evening sun
  sun.direction = {0.0f, -0.22f, 1.0f};  // low, from behind the tree towards the camera: a ~60 m shadow
  sun.shadow.depth_format = DepthFormat::d24;
  d.lights.push_back(sun);
  return d;
}

}  // namespace scenes::builtin
