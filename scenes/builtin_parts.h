// Pieces shared by the built-in scene definitions (builtin_*.cpp): short constructors for materials, objects,
// cameras and lights, and one function per scene. Internal to the scenes module.
#pragma once
#include <string>

#include "scenes/scene_desc.h"

namespace scenes::builtin {

Material material(std::string name, glm::vec3 color, float specular_strength = 0.3f, float shininess = 5.0f);
ObjectDesc object(std::string name, Shape shape, glm::vec3 translate, std::string material,
                  glm::vec3 rotate_deg = glm::vec3(0.0f));
Camera camera(std::string name, glm::vec3 position, glm::vec3 target, float fovy_deg, float near, float far);
Light light(std::string name, LightType type, ShadowTechnique technique);

SceneDesc tutorial(bool spot);
SceneDesc pyramid();
SceneDesc paraboloid();
SceneDesc projective(double time, int figures = 5);
SceneDesc duel();

}  // namespace scenes::builtin
