// The scene JSON format: a document with every field set away from its default survives write -> read
// unchanged (and builds to an equal Scene), shorthands read as documented, and docs/examples/*.json all load.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scenes/builtin_scenes.h"
#include "scenes/scene_build.h"
#include "scenes/scene_json.h"
#include "scenes/scene_queries.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

scenes::Light every_light_field(scenes::LightType type, scenes::ShadowTechnique technique) {
  scenes::Light l;
  l.name = "light " + std::string(to_string(type));
  l.type = type;
  l.color = {0.9f, 0.8f, 0.7f};
  l.intensity = 2.5f;
  if (type != scenes::LightType::directional) {
    l.position = {1.25f, 7.0f, -3.5f};
    l.range = 33.0f;
  }
  if (type != scenes::LightType::point) l.direction = {0.1f, -0.9f, 0.3f};
  if (type == scenes::LightType::spot) {
    l.inner_cone_deg = 12.5f;
    l.outer_cone_deg = 31.0f;
  }
  scenes::ShadowSettings& s = l.shadow;
  s.technique = technique;
  s.filter = scenes::ShadowFilter::early_bail;
  s.bias = {scenes::BiasMode::normal, 0.001f, 0.002f, 0.02f, 2.5f, 8.0f, 0.07f};
  s.cull_front = true;
  s.map_size = 2048;
  s.depth_format = scenes::DepthFormat::d32f;
  s.poisson_taps = 16;
  s.poisson_spread = 1.0f / 300.0f;
  // A parameter of every kind the technique takes, away from its default.
  if (shading::tech::info(technique).reads_filter) s.params = {{"pcf_taps", true}, {"stratify", std::string("world")}};
  if (technique == scenes::ShadowTechnique::shadowmap) s.params["fit"] = std::string("fixed");
  if (technique == scenes::ShadowTechnique::projective) s.params = {{"max_textures", 6.0}, {"caster_shade", 0.25}};
  return l;
}

// A document in which every field differs from its default.
scenes::SceneDesc every_field(const std::string& gltf_path) {
  scenes::SceneDesc d;
  d.name = "everything";
  d.description = "every field away from its default";
  scenes::Material paint;
  paint.name = "paint";
  paint.base_color = {0.1f, 0.2f, 0.3f, 0.4f};
  paint.texture = "textures/paint.png";
  paint.specular_color = {0.5f, 0.6f, 0.7f};
  paint.specular_strength = 0.8f;
  paint.shininess = 33.0f;
  paint.double_sided = true;
  paint.alpha_mode = scenes::AlphaMode::mask;
  paint.alpha_cutoff = 0.375f;
  d.materials.push_back(paint);
  scenes::Material plain;
  plain.name = "plain";
  plain.base_color = {0.7f, 0.7f, 0.7f, 1.0f};
  d.materials.push_back(plain);

  using namespace scenes;
  const Shape shapes[] = {PlaneShape{{3, 4}, 5},       BoxShape{{1, 2, 3}},
                          SphereShape{0.7f, 17, 9},     CylinderShape{0.3f, 2.5f, 11, false},
                          ConeShape{0.4f, 1.5f, 13, false},
                          RoomShape{{8, 3, 9}, 0.25f, room_ceiling | room_pos_x | room_pos_z},
                          TerrainShape{{30, 20}, 17, 1.5f, 9.0f, 42}};
  ObjectDesc group;
  group.name = "group";
  group.transform.translate = {1, 2, 3};
  group.transform.rotate_deg = {10, 20, 30};
  group.transform.scale = {2, 2, 2};
  group.material = "paint";
  group.casts_shadows = false;
  group.receives_shadows = false;
  for (const Shape& shape : shapes) {
    ObjectDesc o;
    o.name = std::string(shape_name(shape));
    o.source = shape;
    o.transform.quaternion = glm::quat(0.5f, 0.5f, -0.5f, 0.5f);
    o.transform.scale = {1, -1, 1};
    o.casts_shadows = true;
    group.children.push_back(o);
  }
  d.objects.push_back(group);

  ObjectDesc model;
  model.name = "model";
  model.source = GltfRef{gltf_path, false, false};
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(4, 5, 6, 1);
  m[0][1] = 0.25f;
  model.transform.matrix = m;
  model.material = "plain";
  d.objects.push_back(model);

  ObjectDesc inline_mesh;
  inline_mesh.name = "triangle";
  Mesh tri;
  tri.name = "tri";
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  tri.texcoords = {{0, 0}, {1, 0}, {0, 1}};
  tri.indices = {0, 1, 2};
  inline_mesh.source = tri;
  d.objects.push_back(inline_mesh);

  Camera persp;
  persp.name = "persp";
  persp.position = {1, 2, 3};
  persp.target = {-1, 0.5f, -2};
  persp.up = {0, 0.8f, 0.6f};
  persp.projection = Perspective{60.0f, 1.5f, 0.25f, 250.0f};
  Camera ortho;
  ortho.name = "ortho";
  ortho.projection = Orthographic{-4, 5, -6, 7, -8, 9};
  d.cameras = {persp, ortho};

  d.lights = {every_light_field(LightType::directional, ShadowTechnique::shadowmap),
              every_light_field(LightType::spot, ShadowTechnique::projective),
              every_light_field(LightType::point, ShadowTechnique::paraboloid),
              every_light_field(LightType::hemispherical, ShadowTechnique::pyramid)};
  return d;
}

TEST(SceneJson, EveryFieldRoundTrips) {
  const auto dir = testsupport::temp_dir("scene_json_round_trip");
  testsupport::GltfFixture f;
  const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  f.node({{"mesh", f.mesh(f.positions(quad), f.indices({0, 1, 2, 2, 1, 3}))}});
  f.write_glb(dir, "quad");

  const scenes::SceneDesc d = every_field("quad.glb");
  // Guard against a field silently left at its default (then the round trip would prove nothing about it).
  EXPECT_NE(d.lights[0].shadow, scenes::ShadowSettings{});
  EXPECT_NE(d.materials[0], scenes::Material{});

  const std::string text = scenes::scene_json_text(d);
  const scenes::SceneDesc back = scenes::parse_scene_json(text, "round-trip.json");
  EXPECT_EQ(back, d) << text;
  EXPECT_EQ(scenes::scene_json_text(back), text) << "writing is stable";

  std::ofstream(dir / "scene.json", std::ios::binary) << text;  // as `shadowlab scene export` writes it
  const scenes::Scene a = scenes::build_scene(d, {dir, "scene.json"});
  const scenes::Scene b = scenes::load_scene(dir / "scene.json");
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.cameras.size(), 2u) << "the glTF's cameras are not imported";
  EXPECT_EQ(a.lights.size(), 4u);
  EXPECT_EQ(a.materials[0].texture, (dir / "textures/paint.png").lexically_normal().generic_string());
}

TEST(SceneJson, EveryBuiltinRoundTrips) {
  for (const scenes::BuiltinInfo& info : scenes::list_builtin_scenes()) {
    const scenes::SceneDesc d = scenes::builtin_scene_desc(info.name, {2.5});
    const scenes::SceneDesc back = scenes::parse_scene_json(scenes::scene_json_text(d), std::string(info.name));
    EXPECT_EQ(back, d) << info.name;
    EXPECT_EQ(scenes::build_scene(back, {{}, std::string(info.name)}), scenes::builtin_scene(info.name, {2.5}))
        << info.name;
  }
}

TEST(SceneJson, ShorthandsReadAsDocumented) {
  const scenes::SceneDesc d = scenes::parse_scene_json(R"({
    "objects": [{"primitive": {"type": "box"}, "transform": {"scale": 2}}],
    "lights": [{"type": "directional", "to_light": [0.5, 2, 2], "shadow": {"bias": "constant"}},
               {"type": "point", "position": [0, 3, 0]}],
    "materials": [{"name": "m", "base_color": [0.5, 0.5, 0.5]}]
  })", "short.json");
  EXPECT_EQ(d.objects[0].transform.scale, glm::vec3(2.0f));
  EXPECT_EQ(d.lights[0].direction, glm::vec3(-0.5f, -2.0f, -2.0f));
  EXPECT_EQ(d.lights[0].shadow.bias.mode, scenes::BiasMode::constant);
  EXPECT_FLOAT_EQ(d.lights[0].shadow.bias.constant, 0.005f);
  EXPECT_EQ(d.lights[1].shadow.technique, scenes::ShadowTechnique::cube) << "default for a point light";
  EXPECT_EQ(d.materials[0].base_color.a, 1.0f);
  const scenes::Scene s = scenes::build_scene(d, {{}, "short.json"});
  EXPECT_NEAR(glm::distance(scenes::to_light(s.lights[0]), glm::normalize(glm::vec3(0.5f, 2, 2))), 0.0f, 1e-6f);
  EXPECT_GT(s.lights[1].range, 3.0f) << "range 0 reaches the whole scene";
  EXPECT_EQ(s.cameras.size(), 1u) << "a framing camera is added";
}

// A light that names a technique but no map size gets that technique's size: small maps per caster for
// projective, 1024² otherwise; a given size is kept.
TEST(SceneJson, MapSizeDefaultsFollowTheTechnique) {
  const scenes::SceneDesc d = scenes::parse_scene_json(R"({
    "objects": [{"primitive": {"type": "box"}}],
    "lights": [{"type": "directional", "shadow": {"technique": "projective"}},
               {"type": "directional", "shadow": {"technique": "projective", "map_size": 64}},
               {"type": "directional", "shadow": {"technique": "shadowmap"}},
               {"type": "point"}]
  })", "sizes.json");
  EXPECT_EQ(d.lights[0].shadow.map_size, 128u);
  EXPECT_EQ(d.lights[1].shadow.map_size, 64u);
  EXPECT_EQ(d.lights[2].shadow.map_size, 1024u);
  EXPECT_EQ(d.lights[3].shadow.map_size, 1024u);
}

// Likewise the depth format (docs/scene-format.md): d32f for the filterable maps, d24 for the warped ones and
// PCSS, d16 for the classic map; a given format is kept.
TEST(SceneJson, DepthFormatDefaultsFollowTheTechnique) {
  const scenes::SceneDesc d = scenes::parse_scene_json(R"({
    "objects": [{"primitive": {"type": "box"}}],
    "lights": [{"type": "directional", "shadow": {"technique": "esm"}},
               {"type": "directional", "shadow": {"technique": "esm", "depth_format": "d16"}},
               {"type": "directional", "shadow": {"technique": "lispsm"}},
               {"type": "spot", "shadow": {"technique": "pcss"}},
               {"type": "directional", "shadow": {"technique": "shadowmap"}},
               {"type": "point", "shadow": {"technique": "irregular"}}]
  })", "formats.json");
  using D = raster::DepthFormat;
  EXPECT_EQ(d.lights[0].shadow.depth_format, D::d32f);
  EXPECT_EQ(d.lights[1].shadow.depth_format, D::d16);
  EXPECT_EQ(d.lights[2].shadow.depth_format, D::d24);
  EXPECT_EQ(d.lights[2].shadow.map_size, 2048u);
  EXPECT_EQ(d.lights[3].shadow.depth_format, D::d24);
  EXPECT_EQ(d.lights[4].shadow.depth_format, D::d16);
  EXPECT_EQ(d.lights[5].shadow.depth_format, D::d32f);
}

TEST(SceneJson, ExamplesLoad) {
  const std::filesystem::path examples = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "docs/examples";
  size_t loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("shared/assets") != std::string::npos && !testsupport::have_assets()) continue;
    SCOPED_TRACE(entry.path().filename().string());
    const scenes::Scene s = scenes::load_scene(entry.path());
    EXPECT_GT(scenes::triangle_count(s), 0u);
    EXPECT_FALSE(s.cameras.empty());
    EXPECT_FALSE(s.lights.empty());
    // Examples are written in canonical form or close to it: they survive a round trip too.
    const scenes::SceneDesc d = scenes::load_scene_desc(entry.path());
    EXPECT_EQ(scenes::parse_scene_json(scenes::scene_json_text(d), "again"), d);
    ++loaded;
  }
  EXPECT_GE(loaded, 3u);
}

}  // namespace
