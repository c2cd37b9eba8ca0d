// The scene JSON format (docs/scene-format.md, docs/scene.schema.json): reading a document strictly (unknown keys,
// wrong types and bad values are SceneErrors naming the key path) and writing one back so that
// read(write(d)) == d for every document d.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "scenes/scene_desc.h"

namespace scenes {

// The format version written and accepted (`"version": 1`; absent means 1).
inline constexpr int kSceneFormatVersion = 1;

// Parses a document; `file` labels errors. Nothing is opened: glTF references are resolved by build_scene().
SceneDesc parse_scene_json(std::string_view text, const std::string& file);

// Reads and parses a scene file; errors are labelled with the path as given.
SceneDesc load_scene_desc(const std::filesystem::path& path);

// The document as JSON text (two-space indent, keys in a fixed order, floats in their shortest exact form).
std::string scene_json_text(const SceneDesc& desc);

}  // namespace scenes
