// A scene frame tests light on their own: a 40 m square of floor (y = 0, facing up, no specular) of a given
// albedo, seen straight from above by an orthographic camera whose 32 x 18 m view fills a 16:9 frame. No light:
// each test adds the one it measures.
#pragma once
#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace testsupport {

inline scenes::Scene floor_seen_from_above(glm::vec3 albedo) {
  scenes::Scene s;
  scenes::Mesh m;
  m.positions = {{-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 2, 1, 0, 3, 2};
  s.meshes.push_back(m);
  scenes::Material mat;
  mat.base_color = glm::vec4(albedo, 1.0f);
  mat.specular_strength = 0.0f;
  s.materials.push_back(mat);
  s.instances.push_back(scenes::Instance{});
  s.objects.push_back("floor");
  scenes::Camera cam;
  cam.position = {0, 50, 0};
  cam.target = {0, 0, 0};
  cam.up = {0, 0, -1};
  cam.projection = scenes::Orthographic{-16.0f, 16.0f, -9.0f, 9.0f, 1.0f, 100.0f};
  s.cameras.push_back(cam);
  return s;
}

}  // namespace testsupport
