// The built-in `projective` scene: simple figures (body, head, hat) walking over uneven terrain, each marked as
// a caster while the terrain only receives, for per-caster projective shadows. `time` (seconds) moves each
// figure along its own circle, standing on the terrain surface and facing where it walks; up to five
// `figures` are the default walkers, more stand in a crowd on a grid (the benchmarks' 10 and 100 casters).
#include <cmath>
#include <numbers>
#include <string>

#include "scenes/builtin_parts.h"
#include "scenes/primitives.h"

namespace scenes::builtin {
namespace {

struct Walk {
  glm::vec2 centre;
  float radius;
  float speed;  // radians per second, negative: clockwise
  float phase;
  const char* colour;
};

constexpr Walk kWalks[] = {
    {{-4.0f, -3.0f}, 2.0f, 0.35f, 0.0f, "red"},    {{4.0f, -3.5f}, 2.0f, -0.45f, 1.0f, "blue"},
    {{0.0f, 0.5f}, 2.5f, 0.25f, 2.0f, "yellow"},   {{-3.5f, 3.5f}, 1.5f, -0.5f, 3.0f, "green"},
    {{3.5f, 3.5f}, 2.0f, 0.3f, 4.0f, "purple"},
};

ObjectDesc figure(int index, const Walk& w, const TerrainShape& ground, double time) {
  const float angle = w.phase + w.speed * float(time);
  const glm::vec2 at = w.centre + w.radius * glm::vec2(std::cos(angle), std::sin(angle));
  // Walking direction is the circle's tangent; yaw turns the figure's +Z towards it.
  const glm::vec2 heading = (w.speed >= 0.0f ? 1.0f : -1.0f) * glm::vec2(-std::sin(angle), std::cos(angle));
  ObjectDesc f;
  f.name = "figure " + std::to_string(index);
  f.transform.translate = {at.x, terrain_height(ground, at.x, at.y), at.y};
  f.transform.rotate_deg = {0.0f, glm::degrees(std::atan2(heading.x, heading.y)), 0.0f};
  f.casts_shadows = true;
  f.receives_shadows = false;
  f.children.push_back(object("body", CylinderShape{0.3f, 1.1f, 24, true}, {0.0f, 0.55f, 0.0f}, w.colour));
  f.children.push_back(object("head", SphereShape{0.25f, 24, 12}, {0.0f, 1.35f, 0.0f}, "skin"));
  f.children.push_back(
      object("nose", ConeShape{0.08f, 0.2f, 12, true}, {0.0f, 1.35f, 0.3f}, "skin", {90.0f, 0.0f, 0.0f}));
  f.children.push_back(object("hat", ConeShape{0.3f, 0.45f, 24, true}, {0.0f, 1.75f, 0.0f}, w.colour));
  return f;
}

}  // namespace

SceneDesc projective(double time, int figures) {
  SceneDesc d;
  d.materials = {material("grass", {0.40f, 0.60f, 0.30f}, 0.05f, 2.0f), material("skin", {0.90f, 0.75f, 0.60f}),
                 material("red", {0.80f, 0.20f, 0.20f}),   material("blue", {0.20f, 0.35f, 0.85f}),
                 material("yellow", {0.90f, 0.80f, 0.20f}), material("green", {0.20f, 0.55f, 0.30f}),
                 material("purple", {0.55f, 0.30f, 0.70f})};
  const TerrainShape ground{{40.0f, 40.0f}, 96, 0.8f, 14.0f, 7};
  ObjectDesc terrain = object("terrain", ground, {0, 0, 0}, "grass");
  terrain.casts_shadows = false;
  terrain.receives_shadows = true;
  d.objects.push_back(terrain);
  if (figures <= 5) {
    for (int i = 0; i < figures; ++i) d.objects.push_back(figure(i, kWalks[i], ground, time));
  } else {
    // A crowd (benchmarks): one figure per cell of a square grid over the middle 32 × 32 m, each on a small
    // circle of its own, colours and speeds cycling through those of the five walkers.
    const int side = int(std::ceil(std::sqrt(double(figures))));
    const float cell = 32.0f / float(side);
    for (int i = 0; i < figures; ++i) {
      const Walk& base = kWalks[i % 5];
      const glm::vec2 centre(-16.0f + cell * (float(i % side) + 0.5f), -16.0f + cell * (float(i / side) + 0.5f));
      d.objects.push_back(figure(i, Walk{centre, 0.3f * cell, base.speed, float(i), base.colour}, ground, time));
    }
  }
  d.cameras.push_back(camera("main", {0.0f, 9.0f, 16.0f}, {0.0f, 0.0f, -1.0f}, 50.0f, 0.5f, 100.0f));

  Light sun = light("sun", LightType::directional, ShadowTechnique::projective);
  sun.intensity = 100000.0f;  // lux: a clear-day sun
  sun.direction = -glm::vec3(0.6f, 1.2f, 0.5f);
  sun.shadow.map_size = 256;  // per caster
  sun.shadow.bias.mode = BiasMode::none;
  d.lights.push_back(sun);
  return d;
}

}  // namespace scenes::builtin
