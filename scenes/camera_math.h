// Matrices of a scene camera (GL conventions: glm::lookAt, glm::perspective / glm::ortho, clip z in [-w, w])
// and a camera framing a bounding box, used when a scene brings no camera of its own.
#pragma once
#include <string>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "scenes/scene_queries.h"

namespace scenes {

glm::mat4 view_matrix(const Camera& camera);
// `viewport_aspect` (width / height) is used when the camera does not fix its own aspect.
glm::mat4 projection_matrix(const Camera& camera, float viewport_aspect);
// The aspect a camera renders with: its own, or the viewport's.
float camera_aspect(const Camera& camera, float viewport_aspect);

// A 45° perspective camera looking at the box's centre from the front, right and above (direction
// (0.6, 0.5, 1)), far enough that the box's bounding sphere fits the view at aspect 1.
Camera frame_camera(const Aabb& bounds, std::string name = "default");

}  // namespace scenes
