// Mesh repairs and conversions used by every loader: area-weighted normals, replacing missing or non-finite
// normals, flipping the winding, triangle strips and fans to lists, and the checks a mesh must pass.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace scenes {

// Vertex normals as the normalised sum of the (unnormalised, hence area-weighted) normals of the triangles
// using each vertex. A vertex no triangle gives a direction gets (0, 1, 0).
std::vector<glm::vec3> compute_normals(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

// Fills `mesh.normals` when empty and replaces every non-finite or zero-length normal by the computed one.
// Returns how many normals were replaced (0 when the mesh had none: they were all computed).
size_t repair_normals(Mesh& mesh);

// Reverses every triangle (a, b, c) -> (a, c, b): front faces become back faces.
void flip_winding(Mesh& mesh);

// glTF TRIANGLE_STRIP / TRIANGLE_FAN to a triangle list, following the glTF 2.0 ordering (strip triangle i:
// v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]; fan triangle i: v[i + 1], v[i + 2], v[0]) so front faces stay
// counter-clockwise. Triangles with a repeated index (restart padding) are dropped.
std::vector<uint32_t> strip_to_list(std::span<const uint32_t> strip);
std::vector<uint32_t> fan_to_list(std::span<const uint32_t> fan);

// Whether some triangle of the mesh has non-zero area once placed by `transform` (it stops at the first, so
// real meshes pay nothing; a zero scale flattens every triangle).
bool has_triangle_with_area(const Mesh& mesh, const glm::mat4& transform = glm::mat4(1.0f));

// What is wrong with a mesh, or nothing: no triangles, an index count that is not a multiple of 3, an index
// out of range, a non-finite position, texture coordinates or normals that do not match the positions.
std::optional<std::string> mesh_problem(const Mesh& mesh);

}  // namespace scenes
