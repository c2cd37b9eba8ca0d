// The built-in `pyramid` and `paraboloid` scenes: a 180° light under the ceiling of a closed room looking down
// on furniture (pyramid map), and a point light with objects above, below and all around it (dual paraboloid).
#include <cmath>
#include <string>

#include "scenes/builtin_parts.h"

namespace scenes::builtin {
namespace {

// A table: a top on four legs, one object with five parts, standing on y = 0.
ObjectDesc table(glm::vec3 at, float yaw_deg) {
  ObjectDesc t;
  t.name = "table";
  t.transform.translate = at;
  t.transform.rotate_deg = {0.0f, yaw_deg, 0.0f};
  t.material = "wood";
  t.children.push_back(object("top", BoxShape{{2.4f, 0.1f, 1.4f}}, {0.0f, 0.95f, 0.0f}, "wood"));
  for (float x : {-1.05f, 1.05f})
    for (float z : {-0.55f, 0.55f})
      t.children.push_back(object("leg", BoxShape{{0.1f, 0.9f, 0.1f}}, {x, 0.45f, z}, "wood"));
  return t;
}

}  // namespace

SceneDesc pyramid() {
  SceneDesc d;
  d.materials = {material("room", {0.80f, 0.78f, 0.74f}), material("wood", {0.55f, 0.38f, 0.22f}),
                 material("red", {0.80f, 0.25f, 0.20f}, 0.5f, 20.0f), material("blue", {0.25f, 0.40f, 0.80f}),
                 material("green", {0.30f, 0.65f, 0.35f})};
  // Interior 10 x 4 x 10 m: floor, ceiling and three walls; the +Z side is open for the camera.
  d.objects.push_back(object("room", RoomShape{{10.0f, 4.0f, 10.0f}, 0.3f,
                                               room_floor | room_ceiling | room_neg_x | room_pos_x | room_neg_z},
                             {0, 0, 0}, "room"));
  d.objects.push_back(table({-1.5f, 0.0f, -1.0f}, 15.0f));
  d.objects.push_back(object("ball", SphereShape{0.6f, 48, 24}, {2.0f, 0.6f, 1.0f}, "red"));
  d.objects.push_back(object("column", CylinderShape{0.4f, 2.0f, 40, true}, {2.5f, 1.0f, -2.5f}, "blue"));
  d.objects.push_back(object("cone", ConeShape{0.6f, 1.5f, 40, true}, {-2.5f, 0.75f, 2.0f}, "green"));
  d.objects.push_back(object("crate", BoxShape{{1.0f, 1.0f, 1.0f}}, {0.5f, 0.5f, 2.5f}, "wood", {0.0f, 30.0f, 0.0f}));
  d.cameras.push_back(camera("main", {0.0f, 2.6f, 11.0f}, {0.0f, 1.2f, 0.0f}, 50.0f, 0.3f, 40.0f));

  Light l = light("ceiling lamp", LightType::hemispherical, ShadowTechnique::pyramid);
  l.position = {0.0f, 3.6f, 0.0f};
  l.intensity = 1000.0f;  // candela: about 75 lux on the floor below, a lit room
  l.direction = {0.0f, -1.0f, 0.0f};
  l.range = 12.0f;
  l.shadow.depth_format = DepthFormat::d24;
  // Measured against the ray-cast reference (eval, 1280x720): the slope bias at 1024² left 120 false-shadowed
  // and 105 false-lit pixels in runs of up to 12 at the furniture's contacts (the slope term grows where the
  // pyramid's faces see the floor at grazing angles); a constant bias at 2048² leaves 56 and 44, runs of 3.
  l.shadow.bias.mode = BiasMode::constant;
  l.shadow.map_size = 2048;
  d.lights.push_back(l);
  return d;
}

SceneDesc paraboloid() {
  SceneDesc d;
  d.materials = {material("ground", {0.70f, 0.70f, 0.68f}), material("stone", {0.65f, 0.60f, 0.55f}),
                 material("red", {0.80f, 0.25f, 0.20f}, 0.5f, 20.0f), material("blue", {0.25f, 0.40f, 0.80f})};
  d.objects.push_back(object("ground", BoxShape{{30.0f, 0.2f, 30.0f}}, {0.0f, -0.1f, 0.0f}, "ground"));
  // Eight pillars on a 5 m circle reach above the light (at 2.5 m), so their shadows cross both hemispheres.
  for (int k = 0; k < 8; ++k) {
    const float a = glm::radians(45.0f * float(k) + 22.5f);
    d.objects.push_back(object("pillar " + std::to_string(k), BoxShape{{0.6f, 4.5f, 0.6f}},
                               {5.0f * std::sin(a), 2.25f, 5.0f * std::cos(a)}, "stone",
                               {0.0f, glm::degrees(a), 0.0f}));
  }
  // Four spheres level with the light and four boxes on the ground, between the pillars.
  for (int k = 0; k < 4; ++k) {
    const float a = glm::radians(90.0f * float(k));
    d.objects.push_back(object("sphere " + std::to_string(k), SphereShape{0.45f, 40, 20},
                               {2.2f * std::sin(a), 2.5f, 2.2f * std::cos(a)}, "red"));
    const float b = a + glm::radians(45.0f);
    d.objects.push_back(object("box " + std::to_string(k), BoxShape{{0.8f, 0.8f, 0.8f}},
                               {3.0f * std::sin(b), 0.4f, 3.0f * std::cos(b)}, "blue", {0.0f, 20.0f * float(k), 0.0f}));
  }
  d.cameras.push_back(camera("main", {0.0f, 10.0f, 14.0f}, {0.0f, 1.0f, 0.0f}, 50.0f, 0.5f, 60.0f));

  Light l = light("lamp", LightType::point, ShadowTechnique::paraboloid);
  l.position = {0.0f, 2.5f, 0.0f};
  l.intensity = 1000.0f;  // candela: 160 lux on the ground below
  l.range = 25.0f;
  l.shadow.depth_format = DepthFormat::d24;
  d.lights.push_back(l);
  return d;
}

}  // namespace scenes::builtin
