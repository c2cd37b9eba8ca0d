// Readers for the geometry parts of a scene document: a transform, a built-in primitive (`"primitive": {...}`)
// and an inline mesh (`"mesh": {...}`). Used by the scene JSON reader; each checks keys, types and values.
#pragma once
#include "scenes/json_in.h"
#include "scenes/scene_desc.h"

namespace scenes {

TransformDesc read_transform(const JsonIn& j);
Shape read_shape(const JsonIn& j);
Mesh read_mesh(const JsonIn& j);

}  // namespace scenes
