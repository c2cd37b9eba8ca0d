// The glTF JSON's indices and byte counts, checked before tinygltf reads the file: tinygltf takes a negative or
// fractional one as absent or as 0 (a bufferView's byteOffset of -4 read as 0, a primitive's "indices": -1 as
// an unindexed primitive, "scene": -1 as no default scene), so such a file drew something without a word.
#pragma once
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace scenes {

struct GltfJsonProblem {
  std::string key;      // where, as the importer names it: "bufferViews[1].byteOffset"
  std::string message;  // what is wrong with it
};

// The first index or byte count of a .gltf document (binary false) or of a GLB's JSON chunk that is not a whole
// number of 0 or more (indices at most 2^31 - 1, the loader's int), an index past the end of the array it names
// (a mesh, node, accessor, buffer view, buffer, camera, material, skin, image, scene or KHR light), a byteStride
// outside glTF's 4..252 in steps of 4, or a primitive mode outside 0..6. Checked:
// every glTF 2.0 property that holds an index (buffer, bufferView, camera, children, indices, index,
// inverseBindMatrices, joints, light, material, mesh, node, nodes, input, output, sampler, scene, skeleton, skin,
// source, the values of attributes and of morph targets), a byte count (byteOffset, byteLength, byteStride,
// count) or texCoord, through the core objects and the two extensions the importer reads (KHR_lights_punctual,
// KHR_texture_transform); "extras" and every other extension are left alone, since their fields follow their own
// rules (Draco's attribute ids, meshopt's byteStride of 2, KHR_interactivity's graph nodes, EXT_lights_image_based's
// lights, KHR_xmp_json_ld's free JSON-LD) and tinygltf keeps them as opaque values. A document nested deeper than
// 256 levels is refused before it is parsed
// (tinygltf's recursion overflowed the stack). A document that does not parse is left to tinygltf to report.
// Also an accessor without its componentType, count or type or with one glTF does not define; a buffer without
// its byteLength, or without a uri where it needs one (every buffer of a .gltf file, all but the first of a .glb);
// a data: URI that is not base64; and, given the file's folder `dir`, a buffer file that is not there.
std::optional<GltfJsonProblem> gltf_json_problem(const unsigned char* bytes, size_t length, bool binary,
                                                 const std::filesystem::path* dir = nullptr);

// A URI's %XX escapes decoded (glTF URIs are percent-encoded: "my%20model.bin" is the file "my model.bin").
std::string gltf_uri_decode(const std::string& uri);

}  // namespace scenes
