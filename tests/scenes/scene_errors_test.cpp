// Bad input of every kind ends in a SceneError whose what() is exactly `WHERE: what is wrong`, WHERE being the
// file and, where there is one, the key path inside it: missing files, malformed JSON and glTF (truncated, a GLB
// header that lies about its length), unknown names, wrong types, unknown keys, non-finite data, empty meshes.
#include <functional>
#include <fstream>
#include <limits>

#include <glm/geometric.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenes/builtin_scenes.h"
#include "scenes/gltf_import.h"
#include "scenes/scene_build.h"
#include "scenes/scene_error.h"
#include "scenes/scene_json.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

// The message a call throws, or "" when it does not throw.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const scenes::SceneError& e) {
    return e.what();
  }
  return "";
}

std::string json_error(const std::string& text) {
  return error_of([&] { scenes::build_scene(scenes::parse_scene_json(text, "scene.json"), {{}, "scene.json"}); });
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

TEST(SceneErrors, MissingFiles) {
  EXPECT_EQ(error_of([] { scenes::load_scene("no/such/scene.json"); }),
            "no/such/scene.json: cannot open file (No such file or directory)");
  EXPECT_EQ(error_of([] { scenes::load_scene("no/such/model.glb"); }),
            "no/such/model.glb: cannot open file (No such file or directory)");
  EXPECT_EQ(error_of([] { scenes::import_gltf("no/such/model.gltf"); }),
            "no/such/model.gltf: cannot open file (No such file or directory)");
  EXPECT_EQ(error_of([] {
              scenes::build_scene(scenes::parse_scene_json(R"({"objects": [{}, {"gltf": "models/x.glb"}]})", "s.json"),
                                  {"base", "s.json"});
            }),
            "s.json: objects[1].gltf: cannot open 'base/models/x.glb' (No such file or directory)");
}

TEST(SceneErrors, MalformedJson) {
  EXPECT_EQ(json_error(R"({"objects": [)"),
            "scene.json: malformed JSON: parse error at line 1, column 14: syntax error while parsing value - "
            "unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(json_error("[1, 2]"), "scene.json: expected an object");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box", "size": [1, 1, 1e39]}}]})"),
            "scene.json: objects[0].primitive.size[2]: expected a finite number that fits in a float");
}

TEST(SceneErrors, WrongTypesAndUnknownKeys) {
  EXPECT_EQ(json_error(R"({"objects": [{}, {}, {"transform": {"scale": [1, 2]}}]})"),
            "scene.json: objects[2].transform.scale: expected an array of 3 numbers");
  EXPECT_EQ(json_error(R"({"objects": [{"colour": [1, 0, 0]}]})"), "scene.json: objects[0].colour: unknown key");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "sphere", "size": 2}}]})"),
            "scene.json: objects[0].primitive.size: unknown key (sphere primitive)");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "sphere", "radius": "big"}}]})"),
            "scene.json: objects[0].primitive.radius: expected a number");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "sphere", "radius": -1}}]})"),
            "scene.json: objects[0].primitive.radius: must be positive");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "point", "direction": [0, -1, 0]}]})"),
            "scene.json: lights[0].direction: unknown key (point light)");
  EXPECT_EQ(json_error(R"({"objects": [{"casts_shadows": 1}]})"),
            "scene.json: objects[0].casts_shadows: expected true or false");
  EXPECT_EQ(json_error(R"({"objects": [{"transform": {"matrix": [1, 0, 0], "translate": [1, 2, 3]}}]})"),
            "scene.json: objects[0].transform.matrix: cannot be combined with translate");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "spot", "inner_cone": 40, "outer_cone": 30}]})"),
            "scene.json: lights[0]: needs 0 <= inner_cone <= outer_cone < 90 degrees");
  EXPECT_EQ(json_error(R"({"cameras": [{"position": [0, 0, 1], "target": [0, 0, 1]}]})"),
            "scene.json: cameras[0].target: same as position");
  EXPECT_EQ(json_error(R"({"version": 2})"), "scene.json: version: unsupported version (this reader knows version 1)");
}

TEST(SceneErrors, UnknownNames) {
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "pyramid"}}]})"),
            "scene.json: objects[0].primitive.type: unknown primitive 'pyramid' (known: plane, box, sphere, "
            "cylinder, cone, room, terrain)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "area"}]})"),
            "scene.json: lights[0].type: unknown light type 'area' (known: directional, spot, point, hemispherical)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"technique": "raytraced"}}]})"),
            "scene.json: lights[0].shadow.technique: unknown technique 'raytraced' (known: none, shadowmap, cube, "
            "paraboloid, pyramid, projective, cascades, lispsm, frustum-faces, esm, vsm, evsm2, evsm4, pcss, irregular)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"filter": "vsm"}}]})"),
            "scene.json: lights[0].shadow.filter: unknown filter 'vsm' (known: hard, pcf, poisson, stratified, "
            "rotated, early-bail)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"depth_format": "d8"}}]})"),
            "scene.json: lights[0].shadow.depth_format: unknown depth format 'd8' (known: d16, d24, d32f)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"bias": {"mode": "huge"}}}]})"),
            "scene.json: lights[0].shadow.bias.mode: unknown bias mode 'huge' (known: none, constant, slope, offset, "
            "normal)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"technique": "cube"}}]})"),
            "scene.json: lights[0].shadow.technique: technique cube does not serve directional lights (it serves: "
            "point, hemispherical) (use: none, shadowmap, projective, cascades, lispsm, frustum-faces, esm, vsm, evsm2, "
            "evsm4, pcss, irregular)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "point", "shadow": {"technique": "cube", "params": {"fit": "auto"}}}]})"),
            "scene.json: lights[0].shadow.params.fit: technique cube takes no parameter 'fit' (it takes: seamless, "
            "moments, esm_c, blur_radius, moment_mips, light_bleed, min_variance, evsm_positive, evsm_negative, "
            "evsm_min_variance, soft_shadows, light_radius, pcf_taps, stratify, poisson_variant)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "point", "shadow": {"params": {"seamless": 1}}}]})"),
            "scene.json: lights[0].shadow.params.seamless: expected true or false");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "point", "shadow": {"poisson_taps": 8}}]})"),
            "scene.json: lights[0].shadow.poisson_taps: expected 4 or 16");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"}, "material": "gold"}]})"),
            "scene.json: objects[0].material: unknown material 'gold'");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "room", "sides": ["floor", "roof"]}}]})"),
            "scene.json: objects[0].primitive.sides[1]: unknown room side 'roof' (known: floor, ceiling, -x, +x, "
            "-z, +z)");
  EXPECT_EQ(error_of([] { scenes::builtin_scene("teapot"); }),
            "teapot: unknown built-in scene (known: tutorial, tutorial-spot, pyramid, paraboloid, projective, duel)");
}

TEST(SceneErrors, EmptyAndBrokenMeshes) {
  EXPECT_EQ(json_error(R"({"objects": [{"mesh": {"positions": [], "indices": []}}]})"),
            "scene.json: objects[0].mesh: empty mesh (no triangles)");
  EXPECT_EQ(json_error(R"({"objects": [{"mesh": {"positions": [0, 0, 0, 1, 0, 0, 0, 1], "indices": [0, 1, 2]}}]})"),
            "scene.json: objects[0].mesh.positions: expected a flat array of numbers, 3 per vertex");
  EXPECT_EQ(json_error(R"({"objects": [{"mesh": {"positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 5]}}]})"),
            "scene.json: objects[0].mesh: index 2 is 5, out of range for 3 vertices");
  EXPECT_EQ(json_error(R"({"objects": []})"), "scene.json: objects: the scene has no triangles");
  EXPECT_EQ(json_error("{}"), "scene.json: objects: the scene has no triangles");
}

// Geometry that would vanish without a word: flattened, degenerate or beyond float range; and colours no
// surface has.
TEST(SceneErrors, DegenerateGeometryAndImpossibleMaterials) {
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"}, "transform": {"scale": [1, 0, 1]}}]})"),
            "scene.json: objects[0].transform: is singular: it flattens the object to nothing (a zero scale, or a "
            "matrix of rank below 3)");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"},
                           "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,0]}}]})"),
            "scene.json: objects[0].transform.matrix: not an affine transform: its last row must be 0, 0, 0, 1");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"},
                           "transform": {"translate": [3e38, 0, 0], "scale": [3e38, 3e38, 3e38]}}]})"),
            "scene.json: objects[0].transform: takes the object's vertices beyond the range of 32-bit floats");
  // A scene of zero-area triangles alone draws nothing: an error. Beside other objects such a mesh is drawn
  // (tests/scenes/frame/bad_geometry_test.cpp) and named in a warning.
  EXPECT_EQ(json_error(R"({"objects": [{"mesh": {"positions": [0, 0, 0, 0, 0, 0, 0, 0, 0], "indices": [0, 1, 2]}}]})"),
            "scene.json: objects: every triangle of the scene has zero area: nothing would be drawn or cast a shadow");
  EXPECT_EQ(json_error(R"({"objects": [{"mesh": {"positions": [0, 0, 0, 1, 1, 1, 2, 2, 2], "indices": [0, 1, 2]}}]})"),
            "scene.json: objects: every triangle of the scene has zero area: nothing would be drawn or cast a shadow");
  const scenes::Scene mixed = scenes::build_scene(
      scenes::parse_scene_json(R"({"objects": [{"primitive": {"type": "box"}, "transform": {"scale": [-1, 1, 1]}},
        {"mesh": {"positions": [0, 0, 0, 0, 0, 0, 0, 0, 0], "indices": [0, 1, 2]}}]})", "scene.json"),
      {{}, "scene.json"});  // a mirror is no flattening
  ASSERT_EQ(mixed.warnings.size(), 1u);
  EXPECT_EQ(mixed.warnings[0], "scene.json: objects[1].mesh: every triangle has zero area (its vertices coincide or "
                               "lie on a line): it draws nothing");
  EXPECT_EQ(json_error(R"({"materials": [{"name": "m", "base_color": [-1, 2, 0.5]}],
                           "objects": [{"primitive": {"type": "box"}, "material": "m"}]})"),
            "scene.json: materials[0].base_color: each component must lie in [0, 1] (linear reflectance and alpha)");
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"}}],
                           "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0],
                                       "shadow": {"filter": "poisson", "poisson_spread": 1.5}}]})"),
            "scene.json: lights[0].shadow.poisson_spread: must be above 0 and at most 1 (the disc's radius in map "
            "coordinates)");
  // A point light's range far beyond the scene: its maps (distance / range) would lose their depths, and its
  // shadows vanish at 3e38. Drawn as given, but said; a range of ten times the reach is not.
  const auto point_light = [](const char* range) {
    return scenes::build_scene(scenes::parse_scene_json(std::string(R"({"objects": [{"primitive": {"type": "box"}}],
        "lights": [{"type": "point", "position": [0, 3, 0], "range": )") + range + "}]}", "scene.json"),
                               {{}, "scene.json"});
  };
  const scenes::Scene far = point_light("3e38");
  ASSERT_EQ(far.warnings.size(), 1u);
  EXPECT_EQ(far.warnings[0].rfind("scene.json: lights[0].range: 3e+38 m is over 100 times the scene's reach from the "
                                  "light (", 0), 0u) << far.warnings[0];
  EXPECT_FLOAT_EQ(far.lights[0].range, 3e38f);
  EXPECT_TRUE(point_light("30").warnings.empty());
  // A scene so far from the origin that float steps dwarf it: refused (it drew an empty frame); a 10 km terrain
  // 100,000 km out is fine.
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"}, "transform": {"translate": [1e30, 0, 0]}}]})"),
            "scene.json: objects: the scene lies 1e+30 m from the origin, where 32-bit floats step by 1.19e+23 m, "
            "too coarse for its size of 1.41 m: move it nearer the origin");  // its x side collapsed
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"},
                           "transform": {"translate": [1e8, 0, 0], "scale": [1e4, 10, 1e4]}}]})"), "");
  // A light direction so long that its squared length overflows still points somewhere.
  const scenes::Scene lit = scenes::build_scene(
      scenes::parse_scene_json(R"({"objects": [{"primitive": {"type": "box"}}],
        "lights": [{"type": "directional", "to_light": [3e38, 3e38, 0]}]})", "scene.json"),
      {{}, "scene.json"});
  ASSERT_EQ(lit.lights.size(), 1u);
  EXPECT_NEAR(glm::length(glm::normalize(lit.lights[0].direction) - glm::normalize(glm::vec3(-1, -1, 0))), 0.0f, 1e-6f);
}

// Values tinygltf reads without a word but wrongly: a negative, fractional or too large index or byte count (as
// 0 or as absent), an index past its array, TRS beside a matrix (dropped), short arrays (ignored); and values the
// glTF specification bounds that the importer used to take (issue 20's probe of hand-edited files). The .gltf
// and the .glb of the same document give the same message.
TEST(SceneErrors, GltfValuesTinygltfWouldMisread) {
  const auto dir = testsupport::temp_dir("scene_errors_gltf_values");
  const std::string d = dir.generic_string();
  int n = 0;
  const auto error = [&](const std::function<void(nlohmann::json&)>& edit, bool lit = false) {
    testsupport::GltfFixture f;
    f.node({{"mesh", f.mesh(f.positions(kTriangle), f.indices({0, 1, 2}))}});
    if (lit) {
      f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
      f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10}}};
      f.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}}}}};
      f.node({{"translation", {0, 0, 3}}, {"camera", 0}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    }
    edit(f.doc);
    std::string name = "v";
    name += std::to_string(n++);
    const auto after = [](std::string message, const std::string& file) {
      if (message.rfind(file + ": ", 0) != 0) return "unexpected: " + message;
      message.erase(0, file.size() + 2);
      return message;
    };
    const std::string text = after(error_of([&] { scenes::load_scene(f.write_gltf(dir, name)); }), d + "/" + name + ".gltf");
    EXPECT_EQ(after(error_of([&] { scenes::load_scene(f.write_glb(dir, name)); }), d + "/" + name + ".glb"), text);
    return text;
  };
  EXPECT_EQ(error([](auto&) {}), "unexpected: ");  // the fixture itself loads (no message at all)
  EXPECT_EQ(error([](auto&) {}, true), "unexpected: ");
  EXPECT_EQ(error([](auto& j) { j["bufferViews"][0]["byteOffset"] = -4; }),
            "bufferViews[0].byteOffset: -4 is not a whole number of 0 or more");
  EXPECT_EQ(error([](auto& j) { j["accessors"][0]["byteOffset"] = 1.5; }),
            "accessors[0].byteOffset: 1.5 is not a whole number of 0 or more");
  EXPECT_EQ(error([](auto& j) { j["meshes"][0]["primitives"][0]["indices"] = -1; }),
            "meshes[0].primitives[0].indices: -1 is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["scene"] = -1; }), "scene: -1 is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["nodes"][0]["mesh"] = 4294967296.0; }),
            "nodes[0].mesh: 4294967296.0 is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["nodes"][0]["mesh"] = 3; }),
            "nodes[0].mesh: index 3 is past the end of meshes (the file has 1 entry)");
  EXPECT_EQ(error([](auto& j) { j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9; }),
            "meshes[0].primitives[0].attributes.POSITION: index 9 is past the end of accessors (the file has 2 "
            "entries)");
  // Where a number belongs, anything else (tinygltf said "'attributes' value is not an integer type", naming no key).
  EXPECT_EQ(error([](auto& j) { j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = "x"; }),
            "meshes[0].primitives[0].attributes.POSITION: \"x\" is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["nodes"][0]["mesh"] = nullptr; }),
            "nodes[0].mesh: null is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["scenes"][0]["nodes"] = 0; }), "scenes[0].nodes: 0 is not an array of indices");
  EXPECT_EQ(error([](auto& j) { j["scenes"][0]["nodes"] = {"0"}; }),
            "scenes[0].nodes[0]: \"0\" is not an index (a whole number from 0 to 2147483647)");
  EXPECT_EQ(error([](auto& j) { j["accessors"][0]["count"] = "3"; }),
            "accessors[0].count: \"3\" is not a whole number of 0 or more");
  EXPECT_EQ(error([](auto& j) { j["accessors"][0]["type"] = "VEC9"; }),
            "accessors[0].type: \"VEC9\" is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
  EXPECT_EQ(error([](auto& j) { j["accessors"][1].erase("componentType"); }),
            "accessors[1].componentType: missing (an accessor needs it)");
  EXPECT_EQ(error([](auto& j) { j["accessors"][1]["componentType"] = 5124; }),
            "accessors[1].componentType: 5124 is not a component type glTF allows (5120 byte, 5121 unsigned byte, "
            "5122 short, 5123 unsigned short, 5125 unsigned int, 5126 float)");
  EXPECT_EQ(error([](auto& j) { j["meshes"][0]["primitives"][0]["mode"] = -1; }),
            "meshes[0].primitives[0].mode: -1 is not a primitive mode (0 points .. 6 triangle fan)");
  EXPECT_EQ(error([](auto& j) { j["bufferViews"][0]["byteStride"] = 1000; }),
            "bufferViews[0].byteStride: 1000 is not a byte stride glTF allows (a multiple of 4 from 4 to 252)");
  EXPECT_EQ(error([](auto& j) { j["nodes"][0]["matrix"] = {1, 0, 0, 1}; }), "nodes[0].matrix: needs 16 numbers, not 4");
  EXPECT_EQ(error([](auto& j) { j["accessors"][0]["normalized"] = true; }),
            "accessors[0].normalized: only 8- and 16-bit integer components can be normalized");
  EXPECT_EQ(error([](auto& j) {
              j["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
              j["nodes"][0]["translation"] = {5, 0, 0};
            }),
            "nodes[0].matrix: a node has a matrix or translation, rotation and scale, not both");
  EXPECT_EQ(error([](auto& j) { j["nodes"][0]["rotation"] = {0, 0, 0, 0}; }),
            "nodes[0].rotation: is not a unit quaternion (its length is 0.000000)");
  EXPECT_EQ(error([](auto& j) { j["asset"]["version"] = "1.0"; }), "asset.version: '1.0': this importer reads glTF 2.x");
  EXPECT_EQ(error([](auto& j) { j["extensionsRequired"] = {"EXT_unknown"}; }),
            "extensionsRequired: 'EXT_unknown' is not supported (this importer reads KHR_lights_punctual, "
            "KHR_texture_transform and KHR_mesh_quantization)");
  EXPECT_EQ(error([](auto& j) {  // 300 levels of arrays in extras: refused before any parser recurses
              j["extras"] = nlohmann::json::parse(std::string(300, '[') + std::string(300, ']'));
            }),
            "the JSON nests deeper than 256 levels");
  EXPECT_EQ(error([](auto& j) { j["extras"] = {{"mesh", -1}}; }), "unexpected: ");  // extras are the author's own
  EXPECT_EQ(error([](auto& j) {  // Draco's attribute ids (used, not required: the accessors stand) are not accessors
              j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
              j["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
                  {"bufferView", 0}, {"attributes", {{"POSITION", 7}}}};
            }),
            "unexpected: ");
  EXPECT_EQ(error([](auto& j) {  // meshopt's index streams have a byteStride of 2
              j["extensionsUsed"] = {"EXT_meshopt_compression"};
              j["bufferViews"][0]["extensions"]["EXT_meshopt_compression"] = {
                  {"buffer", 0}, {"byteLength", 4}, {"byteStride", 2}, {"count", 2}, {"mode", "INDICES"}};
            }),
            "unexpected: ");
  EXPECT_EQ(error([](auto& j) {  // other extensions give these keys their own meanings; none is checked as core
              j["extensionsUsed"] = {"KHR_interactivity", "EXT_lights_image_based", "KHR_xmp_json_ld"};
              j["extensions"]["KHR_interactivity"] = {
                  {"graphs", {{{"nodes", {{{"declaration", 0}, {"flows", {{"out", {{"node", 5}, {"socket", "in"}}}}}}}}}}}};
              j["extensions"]["EXT_lights_image_based"] = {{"lights", {{{"intensity", 1}}}}};
              j["scenes"][0]["extensions"]["EXT_lights_image_based"] = {{"light", 0}};  // there is no KHR light
              j["extensions"]["KHR_xmp_json_ld"] = {{"packets", {{{"xmp:count", 1}, {"count", 2.5}}}}};
              j["nodes"][0]["extensions"]["KHR_xmp_json_ld"] = {{"packet", 0}};
            }),
            "unexpected: ");
  EXPECT_EQ(error([](auto& j) {  // but KHR_texture_transform, which the importer reads, is
              j["extensionsUsed"] = {"KHR_texture_transform"};
              j["materials"] = {{{"pbrMetallicRoughness",
                                  {{"baseColorTexture",
                                    {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", -1}}}}}}}}}}};
            }),
            "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.texCoord: -1 is not "
            "an index (a whole number from 0 to 2147483647)");
  // Lights, cameras and materials as the specification bounds them.
  EXPECT_EQ(error([](auto& j) { j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -5; }, true),
            "extensions.KHR_lights_punctual.lights[0].intensity: must be a finite number of 0 or more (candela, or "
            "lux for a directional light)");
  EXPECT_EQ(error([](auto& j) { j["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, -1, 1}; }, true),
            "extensions.KHR_lights_punctual.lights[0].color: needs three finite components of 0 or more");
  EXPECT_EQ(error([](auto& j) { j["extensions"]["KHR_lights_punctual"]["lights"][0]["range"] = -1; }, true),
            "extensions.KHR_lights_punctual.lights[0].range: must be a finite number above 0");
  EXPECT_EQ(error([](auto& j) { j["nodes"][1]["scale"] = {0, 0, 0}; }, true),
            "nodes[1]: the node's transform flattens camera 0: its view direction and up vector are zero or parallel");
  EXPECT_EQ(error([](auto& j) { j["cameras"][0]["perspective"]["yfov"] = 3.1415927; }, true),  // drew an empty frame
            "cameras[0].perspective: needs 0 < yfov < pi and a positive znear");
  EXPECT_EQ(error([](auto& j) { j["cameras"][0]["perspective"]["zfar"] = 0.05; }, true),
            "cameras[0].perspective.zfar: must be greater than znear");
  EXPECT_EQ(error([](auto& j) { j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {-1, 2, 0, 1}}}}}};
                                j["meshes"][0]["primitives"][0]["material"] = 0; }),
            "materials[0].pbrMetallicRoughness.baseColorFactor: needs four components, each in [0, 1]");
  EXPECT_EQ(error([](auto& j) { j["materials"] = {{{"pbrMetallicRoughness", {{"roughnessFactor", -3}}}}};
                                j["meshes"][0]["primitives"][0]["material"] = 0; }),
            "materials[0].pbrMetallicRoughness.roughnessFactor: must lie in [0, 1]");
  {  // a .gltf file's buffers, named by their key (tinygltf said "File not found : name.bin")
    testsupport::GltfFixture f;
    f.node({{"mesh", f.mesh(f.positions(kTriangle), f.indices({0, 1, 2}))}});
    const auto buffer_error = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
      const auto path = f.write_gltf(dir, name);
      nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
      edit(j["buffers"][0]);
      std::ofstream(path) << j.dump();
      const std::string message = error_of([&] { scenes::load_scene(path); });
      const std::string file = d + "/" + name + ".gltf: ";
      return message.rfind(file, 0) == 0 ? message.substr(file.size()) : "unexpected: " + message;
    };
    EXPECT_EQ(buffer_error("b0", [](auto&) {}), "unexpected: ");
    EXPECT_EQ(buffer_error("b1", [](auto& b) { b["uri"] = "gone.bin"; }),
              "buffers[0].uri: 'gone.bin': no such file (looked for " + d + "/gone.bin)");
    EXPECT_EQ(buffer_error("b2", [](auto& b) { b.erase("uri"); }),
              "buffers[0].uri: missing (only the first buffer of a .glb file may leave it out, for the file's BIN chunk)");
    EXPECT_EQ(buffer_error("b3", [](auto& b) { b.erase("byteLength"); }), "buffers[0].byteLength: missing (a buffer needs it)");
    EXPECT_EQ(buffer_error("b4", [](auto& b) { b["uri"] = "data:application/octet-stream;base64,@@@"; }),
              "buffers[0].uri: a data: URI whose data is not base64 (data:application/octet-stream;base64,...)");
    // A percent-encoded name is the file's decoded name.
    std::filesystem::copy_file(dir / "b0.bin", dir / "b5 copy.bin", std::filesystem::copy_options::overwrite_existing);
    EXPECT_EQ(buffer_error("b5", [](auto& b) { b["uri"] = "b5%20copy.bin"; }), "unexpected: ");
  }
  {  // a texture read through TEXCOORD_0, which the primitive lacks: drawn (exporters write these), but said
    testsupport::GltfFixture f;
    f.node({{"mesh", f.mesh(f.positions(kTriangle), f.indices({0, 1, 2}))}});
    f.doc["images"] = {{{"uri", "missing.png"}}};
    f.doc["textures"] = {{{"source", 0}}};
    f.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    f.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const scenes::Scene s = scenes::import_gltf(f.write_gltf(dir, "no_uv"));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0], d + "/no_uv.gltf: meshes[0].primitives[0].attributes.TEXCOORD_0: missing, though the "
                                 "material's base-colour texture reads it: the texel at (0, 0) colours the whole "
                                 "primitive");
  }
  // A JSON scene's light colour is bounded alike.
  EXPECT_EQ(json_error(R"({"objects": [{"primitive": {"type": "box"}}],
                           "lights": [{"type": "directional", "color": [-1, 1, 1]}]})"),
            "scene.json: lights[0].color: needs three finite components of 0 or more");
}

TEST(SceneErrors, GltfOutsideTheSpecification) {
  const auto dir = testsupport::temp_dir("scene_errors_gltf_spec");
  const std::string d = dir.generic_string();
  {
    testsupport::GltfFixture f;  // a node matrix whose last row is not 0, 0, 0, 1
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "matrix")); }),
              d + "/matrix.gltf: nodes[0].matrix: not an affine transform: its last row must be 0, 0, 0, 1");
  }
  {
    testsupport::GltfFixture f;  // a spot whose inner cone is wider than its outer one
    f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"}, {"spot", {{"innerConeAngle", 1.0}, {"outerConeAngle", 0.5}}}}};
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    const std::string e = error_of([&] { scenes::load_scene(f.write_gltf(dir, "cones")); });
    EXPECT_EQ(e.rfind(d + "/cones.gltf: nodes[1].extensions.KHR_lights_punctual.light.spot: innerConeAngle 1.0", 0), 0u) << e;
  }
  {
    testsupport::GltfFixture f;  // its only mesh under a node of zero scale (glTF's way of hiding one): nothing drawn
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}, {"scale", {0, 0, 0}}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "hidden")); }),
              d + "/hidden.gltf: every triangle of the file's scene has zero area: nothing would be drawn or cast a "
                  "shadow");
    f.node({{"mesh", 0}});  // beside a visible instance it is fine
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "half_hidden")); }), "");
  }
  {
    testsupport::GltfFixture f;  // a buffer whose uri names a folder (was std::bad_alloc from the loader)
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    const auto path = f.write_gltf(dir, "folder");
    std::filesystem::remove(dir / "folder.bin");
    std::filesystem::create_directory(dir / "folder.bin");
    const std::string e = error_of([&] { scenes::load_scene(path); });
    EXPECT_EQ(e, d + "/folder.gltf: buffers[0].uri: 'folder.bin': not a regular file (looked for " + d + "/folder.bin)");
  }
  {
    testsupport::GltfFixture f;  // a GLB whose header says version 1
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    std::vector<uint8_t> bytes = f.glb_bytes();
    bytes[4] = 1;
    const auto path = testsupport::GltfFixture::write_bytes(dir / "v1.glb", bytes);
    EXPECT_EQ(error_of([&] { scenes::load_scene(path); }),
              d + "/v1.glb: malformed GLB: header version 1 (only glTF 2.0 binaries, version 2, are read)");
  }
}

TEST(SceneErrors, BrokenGltf) {
  const auto dir = testsupport::temp_dir("scene_errors_gltf");
  const std::string d = dir.generic_string();
  {
    testsupport::GltfFixture f;  // NaN position
    std::vector<glm::vec3> p = kTriangle;
    p[1].x = std::numeric_limits<float>::quiet_NaN();
    f.node({{"mesh", f.mesh(f.positions(p))}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "nan")); }),
              d + "/nan.gltf: meshes[0].primitives[0]: vertex 1 has a non-finite position");
  }
  {
    testsupport::GltfFixture f;  // infinite position, in a GLB
    std::vector<glm::vec3> p = kTriangle;
    p[2].z = std::numeric_limits<float>::infinity();
    f.node({{"mesh", f.mesh(f.positions(p))}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_glb(dir, "inf")); }),
              d + "/inf.glb: meshes[0].primitives[0]: vertex 2 has a non-finite position");
  }
  {
    testsupport::GltfFixture f;  // empty primitive (the buffer itself is not empty)
    f.positions(kTriangle);
    f.node({{"mesh", f.mesh(f.positions({}))}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "empty")); }),
              d + "/empty.gltf: meshes[0].primitives[0]: empty mesh (no triangles)");
  }
  {
    testsupport::GltfFixture f;  // index out of range, accessor past the end of its buffer view
    const int positions = f.positions(kTriangle);
    f.node({{"mesh", f.mesh(positions, f.indices({0, 1, 7}))}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "index")); }),
              d + "/index.gltf: meshes[0].primitives[0]: index 2 is 7, out of range for 3 vertices");
    f.doc["accessors"][0]["count"] = 4;
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "overrun")); }),
              d + "/overrun.gltf: meshes[0].primitives[0].attributes.POSITION (accessors[0]): 4 elements at offset 0 "
                  "run past the end of bufferViews[0] (36 bytes)");
  }
  {
    testsupport::GltfFixture f;  // a node that is its own grandchild
    const int a = f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    const int b = f.node({{"children", {a}}}, false);
    f.doc["nodes"][a]["children"] = {b};
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "cycle")); }),
              d + "/cycle.gltf: nodes[1].children: node 0 is reached twice: the node hierarchy has a cycle");
  }
  {
    // Issue 23: a count the buffer cannot hold is refused before anything is allocated for it (2^27 VEC3 would
    // have been 1.5 GB), and a count of 0 is an empty mesh, not a read through a null pointer.
    testsupport::GltfFixture f;
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    f.doc["accessors"][0]["count"] = 1 << 27;
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "huge_count")); }),
              d + "/huge_count.gltf: meshes[0].primitives[0].attributes.POSITION (accessors[0]): 134217728 elements "
                  "at offset 0 run past the end of bufferViews[0] (36 bytes)");
    f.doc["accessors"][0]["count"] = 0;
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "zero_count")); }),
              d + "/zero_count.gltf: meshes[0].primitives[0]: empty mesh (no triangles)");
    // Found by fuzz_gltf's campaign: an accessor without a bufferView (all zeros, legal glTF) claiming 2^28
    // elements allocated 3 GiB before any check. Zeros may number at most the file's buffer bytes (here 36), or
    // 65,536; a small one still loads (a degenerate triangle at the origin).
    f.doc["accessors"][0]["count"] = 1 << 28;
    f.doc["accessors"][0].erase("bufferView");
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "zeros_huge")); }),
              d + "/zeros_huge.gltf: meshes[0].primitives[0].attributes.POSITION (accessors[0]): count 268435456 "
                  "without a bufferView exceeds 65536 (the elements an accessor of zeros may have: the file's buffer "
                  "bytes, at least 65536)");
    // A small one is within the limit, and then what it holds is three zeros: a triangle of no area, which is
    // all the file has, so nothing would be drawn.
    f.doc["accessors"][0]["count"] = 3;
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "zeros_small")); }),
              d + "/zeros_small.gltf: every triangle of the file's scene has zero area: nothing would be drawn or cast "
                  "a shadow");
  }
  {
    // Issue 23: node i lists node i + 1 twice (a DAG): 2^n paths before; now refused at once.
    testsupport::GltfFixture f;
    const int m = f.mesh(f.positions(kTriangle));
    f.node({{"children", {1, 1}}});
    for (int i = 1; i < 40; ++i) f.node({{"mesh", m}, {"children", {i + 1, i + 1}}}, false);
    f.node({{"mesh", m}}, false);
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "dag")); }),
              d + "/dag.gltf: nodes[0].children: node 1 is already a child of node 0: a glTF node has at most one "
                  "parent");
  }
  {
    // A node that is both a root and another node's child is reached twice.
    testsupport::GltfFixture f;
    const int a = f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    f.node({{"children", {a}}});
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "root_child")); }),
              d + "/root_child.gltf: nodes[1].children: node 0 is reached twice: the node hierarchy has a cycle");
  }
  {
    testsupport::GltfFixture f;  // compressed geometry
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    f.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    f.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    EXPECT_EQ(error_of([&] { scenes::load_scene(f.write_gltf(dir, "draco")); }),
              d + "/draco.gltf: extensionsRequired: 'KHR_draco_mesh_compression' is not supported (this importer "
                  "reads KHR_lights_punctual, KHR_texture_transform and KHR_mesh_quantization)");
  }
  {
    // A broken base64 buffer: tinygltf quoted the whole URI (a 240 KB line for a real file); named by its key.
    testsupport::GltfFixture f;
    f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
    nlohmann::json doc = f.doc;
    doc["buffers"] = {{{"uri", "data:application/octet-stream;base64," + std::string(20000, 'A') + "!!"},
                       {"byteLength", 36}}};
    std::ofstream(dir / "datauri.gltf") << doc.dump();
    const std::string message = error_of([&] { scenes::load_scene(dir / "datauri.gltf"); });
    EXPECT_EQ(message, d + "/datauri.gltf: buffers[0].uri: a data: URI whose data is not base64 "
                           "(data:application/octet-stream;base64,...)");
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(20000, 'A');  // 15000 bytes
    std::ofstream(dir / "datauri.gltf") << doc.dump();
    EXPECT_EQ(error_of([&] { scenes::load_scene(dir / "datauri.gltf"); }),
              d + "/datauri.gltf: buffers[0].uri: the data: URI holds 15000 bytes, byteLength says 36");
    doc["buffers"][0]["uri"] = "data:application/json;base64,AAAA";
    std::ofstream(dir / "datauri.gltf") << doc.dump();
    EXPECT_EQ(error_of([&] { scenes::load_scene(dir / "datauri.gltf"); }),
              d + "/datauri.gltf: buffers[0].uri: a data: URI of type 'application/json' (a buffer's is "
                  "application/octet-stream or application/gltf-buffer)");
  }
  testsupport::GltfFixture f;
  f.node({{"mesh", f.mesh(f.positions(kTriangle))}});
  // Truncated glTF JSON.
  const auto gltf = f.write_gltf(dir, "good");
  std::ifstream in(gltf);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "truncated.gltf") << text.substr(0, text.size() / 2);
  EXPECT_THAT(error_of([&] { scenes::load_scene(dir / "truncated.gltf"); }),
              testing::StartsWith(d + "/truncated.gltf: malformed glTF: parse error at line "));
  // A GLB whose header claims more bytes than the file has, and one cut short.
  std::vector<uint8_t> glb = f.glb_bytes();
  std::vector<uint8_t> lying = glb;
  lying[8] = uint8_t(lying[8] + 64);
  testsupport::GltfFixture::write_bytes(dir / "lying.glb", lying);
  EXPECT_EQ(error_of([&] { scenes::load_scene(dir / "lying.glb"); }),
            d + "/lying.glb: malformed GLB: Invalid glTF binary.");
  glb.resize(glb.size() - 8);
  testsupport::GltfFixture::write_bytes(dir / "cut.glb", glb);
  EXPECT_EQ(error_of([&] { scenes::load_scene(dir / "cut.glb"); }),
            d + "/cut.glb: malformed GLB: Invalid glTF binary.");
  // Issue 23: a GLB whose buffer claims 0 bytes ended in "internal error: vector::_M_range_check"; without a
  // BIN chunk, and with one.
  for (const bool bin_chunk : {false, true}) {
    nlohmann::json doc = f.doc;
    doc["buffers"] = nlohmann::json::array({{{"byteLength", 0}}});
    std::string json = doc.dump();
    while (json.size() % 4) json.push_back(' ');
    std::vector<uint8_t> body = f.bin;
    while (body.size() % 4) body.push_back(0);
    std::vector<uint8_t> zero;
    auto u32 = [&](uint32_t v) {
      for (int i = 0; i < 4; ++i) zero.push_back(uint8_t(v >> (8 * i)));
    };
    const size_t total = 12 + 8 + json.size() + (bin_chunk ? 8 + body.size() : 0);
    u32(0x46546C67u), u32(2), u32(uint32_t(total)), u32(uint32_t(json.size())), u32(0x4E4F534Au);
    zero.insert(zero.end(), json.begin(), json.end());
    if (bin_chunk) {
      u32(uint32_t(body.size())), u32(0x004E4942u);
      zero.insert(zero.end(), body.begin(), body.end());
    }
    testsupport::GltfFixture::write_bytes(dir / "zero_buffer.glb", zero);
    EXPECT_THAT(error_of([&] { scenes::load_scene(dir / "zero_buffer.glb"); }),
                testing::StartsWith(d + "/zero_buffer.glb: malformed GLB: "))
        << bin_chunk;
  }
  // Not a glTF at all.
  std::ofstream(dir / "garbage.glb") << "hello";
  EXPECT_EQ(error_of([&] { scenes::load_scene(dir / "garbage.glb"); }),
            d + "/garbage.glb: malformed glTF: parse error at line 1, column 1: syntax error while parsing value - "
                "invalid literal; last read: 'h'");
}

// Issue 23: a scene's bad bias value was reported as the command-line option that would override it; it is
// now refused when the scene is loaded, naming the file and the field.
TEST(SceneErrors, BadBiasValuesNameTheSceneField) {
  EXPECT_EQ(json_error(R"({"lights": [{"type": "directional", "shadow": {"bias": {"slope_max": -1}}}]})"),
            "scene.json: lights[0].shadow.bias.slope_max: must be a finite number of 0 or more");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "spot", "shadow": {"bias": {"mode": "normal", "normal_offset": -0.5}}}]})"),
            "scene.json: lights[0].shadow.bias.normal_offset: must be a finite number of 0 or more");
}

// Issue 23: a scene's map size its technique cannot hold is refused when the scene loads, naming the file.
TEST(SceneErrors, MapSizesTheTechniqueCannotHold) {
  EXPECT_EQ(json_error(R"({"lights": [{"type": "point", "position": [0, 2, 0], "shadow": {"map_size": 8000}}]})"),
            "scene.json: lights[0].shadow.map_size: 8000 is outside 16..5461 for technique cube (its maps share one "
            "target of at most 16384 texels a side)");
  EXPECT_EQ(json_error(R"({"lights": [{"type": "hemispherical", "position": [0, 2, 0], "shadow": {"map_size": 63}}]})"),
            "scene.json: lights[0].shadow.map_size: the pyramid map side 63 must be even (two halves per axis)");
}

// Issue 23: objects nested 20,000 deep overflowed the stack (and 10,000 took 1.8 GB); deeper than 256 levels
// is refused at once, naming the top-level object; 256 levels load.
TEST(SceneErrors, DeeplyNestedObjects) {
  auto nested = [](int depth) {
    std::string s = R"({"objects": [)";
    for (int i = 0; i < depth; ++i) s += R"({"children": [)";
    s += R"({"primitive": {"type": "box"}})";
    for (int i = 0; i < depth; ++i) s += "]}";
    return s + "]}";
  };
  EXPECT_EQ(json_error(nested(20000)), "scene.json: objects[0]: children nest deeper than 256 levels");
  EXPECT_EQ(json_error(nested(256)), "");
}

TEST(SceneErrors, ErrorsCarryTheirParts) {
  try {
    scenes::parse_scene_json(R"({"objects": [{"transform": {"scale": "big"}}]})", "parts.json");
    FAIL() << "no error";
  } catch (const scenes::SceneError& e) {
    EXPECT_EQ(e.file(), "parts.json");
    EXPECT_EQ(e.key_path(), "objects[0].transform.scale");
    EXPECT_EQ(e.message(), "expected an array of 3 numbers");
  }
}

}  // namespace
