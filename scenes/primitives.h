// Procedural meshes for the built-in primitives of the scene format (plane, box, sphere, cylinder, cone,
// thick-walled room, terrain): closed solids where the shape is closed, counter-clockwise front faces pointing
// outwards, normals and texture coordinates filled.
#pragma once
#include "scenes/scene.h"
#include "scenes/scene_desc.h"

namespace scenes {

// The mesh of a primitive, named after it. Parameters must be valid (check_shape() says why not).
Mesh make_shape_mesh(const Shape& shape);

// What is wrong with a primitive's parameters (a size that is not positive, too few segments, ...), or nothing.
// The message starts with the offending key, e.g. "radius: must be positive".
std::optional<std::string> check_shape(const Shape& shape);

// Height of a terrain primitive at (x, z) in its own space; the mesh's vertices lie on this surface.
float terrain_height(const TerrainShape& terrain, float x, float z);

}  // namespace scenes
