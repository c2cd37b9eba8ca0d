// The built-in `tutorial` and `tutorial-spot` scenes: the room of the classic OpenGL shadow-mapping tutorial
// (thick walls so back faces can build the map, a floor, a cylinder and a sphere), lit by its directional light
// towards (0.5, 2, 2) or by its spot light at (5, 20, 20) pointing back along that direction.
#include "scenes/builtin_parts.h"

namespace scenes::builtin {

SceneDesc tutorial(bool spot) {
  SceneDesc d;
  d.materials = {material("room", {0.78f, 0.75f, 0.70f}), material("cylinder", {0.30f, 0.50f, 0.80f}),
                 material("sphere", {0.85f, 0.35f, 0.25f}, 0.5f, 20.0f)};
  // Interior 12 x 5 x 12 m with 0.5 m walls on the left, right and back; open towards the camera and the sky.
  const RoomShape room{{12.0f, 5.0f, 12.0f}, 0.5f, room_floor | room_neg_x | room_pos_x | room_neg_z};
  d.objects.push_back(object("room", room, {0, 0, 0}, "room"));
  d.objects.push_back(object("cylinder", CylinderShape{0.8f, 3.0f, 48, true}, {-2.0f, 1.5f, -1.5f}, "cylinder"));
  d.objects.push_back(object("sphere", SphereShape{1.2f, 48, 24}, {2.2f, 1.2f, 0.8f}, "sphere"));
  d.cameras.push_back(camera("main", {0.0f, 7.5f, 17.0f}, {0.0f, 1.0f, -1.0f}, 45.0f, 0.5f, 60.0f));

  Light l;
  if (!spot) {
    l = light("sun", LightType::directional, ShadowTechnique::shadowmap);
    l.intensity = 100000.0f;  // lux: a clear-day sun
    l.direction = -glm::vec3(0.5f, 2.0f, 2.0f);  // travels from the light: the light is towards (0.5, 2, 2)
  } else {
    l = light("spot", LightType::spot, ShadowTechnique::shadowmap);
    l.position = {5.0f, 20.0f, 20.0f};
    l.intensity = 400000.0f;  // candela: a stadium floodlight, about 510 lux on the floor 28 m away
    l.direction = -glm::vec3(0.5f, 2.0f, 2.0f);  // the axis passes through the origin
    l.inner_cone_deg = 17.5f;
    l.outer_cone_deg = 22.5f;                    // the tutorial's 45° perspective frustum
    l.range = 50.0f;
  }
  l.shadow.filter = ShadowFilter::pcf;
  l.shadow.bias.mode = BiasMode::slope;
  l.shadow.cull_front = true;  // the tutorial draws back faces into the map, in addition to the bias
  if (!spot) {
    // Measured against the ray-cast reference (shadowlab eval, 1280x720): back faces only and a 1024² map left
    // 345 false-lit pixels along the right wall's floor joint and under the sphere (runs of 16); front faces
    // and 2048² leave 20, none longer than a pixel, with no more acne (20 false-shadowed against 22).
    l.shadow.cull_front = false;
    l.shadow.map_size = 2048;
  } else {
    // The spot's map is perspective: near the light's axis a texel spans more of the floor than the sun's, and
    // with front faces the slope bias leaves acne (eval, 1280x720: 12,671 false-shadowed pixels at 1024², 303 at
    // 2048²). Back faces keep it out, and 2048² narrows the leak at the contacts: 13 false-shadowed and 23
    // false-lit pixels (runs of at most 3), against 23 and 38 (runs of 4) at 1024².
    l.shadow.map_size = 2048;
  }
  d.lights.push_back(l);
  return d;
}

}  // namespace scenes::builtin
