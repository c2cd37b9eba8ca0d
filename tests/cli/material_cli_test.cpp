// Material textures through the command line: a scene (JSON or glTF) naming a texture that does not exist fails
// with exit 2 and one error line naming the file and the material, and writes nothing; a masked, textured JSON
// scene renders.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

std::string leaf_json(const std::string& texture) {
  return R"({"version": 1, "name": "leaf",
  "materials": [{"name": "leaf", "texture": ")" + texture + R"(", "alpha_mode": "mask", "alpha_cutoff": 0.5, "double_sided": true}],
  "objects": [
    {"name": "floor", "primitive": {"type": "box", "size": [8, 0.2, 8]}, "transform": {"translate": [0, -0.1, 0]}},
    {"name": "leaf", "primitive": {"type": "plane", "size": [2, 2]}, "material": "leaf", "transform": {"translate": [0, 1.5, 0]}}],
  "cameras": [{"position": [3, 5, 6], "target": [0, 0.5, 0]}],
  "lights": [{"name": "sun", "type": "directional", "to_light": [0.5, 2, 1]}]})";
}

// The one error line of a bad run: exit 2, `shadowlab: error: FILE: ... material 'NAME' ...`, no output file.
void expect_missing_texture(const fs::path& dir, const std::string& args, const std::string& file,
                            const std::string& material) {
  const testsupport::Outcome r = testsupport::shadowlab(dir, args);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_THAT(r.err, ::testing::MatchesRegex("shadowlab: error: [^\n]+\n")) << r.err;
  EXPECT_NE(r.err.find(file + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("material '" + material + "'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

}  // namespace

TEST(MaterialCli, MissingJsonTextureExitsTwoNamingFileAndMaterial) {
  const fs::path dir = testsupport::temp_dir("material_cli_json");
  std::ofstream(dir / "leaf.json") << leaf_json("leaves/missing.png");
  expect_missing_texture(dir, "render leaf.json --size 64x48 --out out.png", "leaves/missing.png", "leaf");
}

TEST(MaterialCli, MissingGltfTextureExitsTwoNamingFileAndMaterial) {
  const fs::path dir = testsupport::temp_dir("material_cli_gltf");
  testsupport::GltfFixture g;
  const int pos = g.positions({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
  const std::vector<glm::vec2> uv{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int tex = g.accessor(uv.data(), uv.size() * sizeof(glm::vec2), 5126, uv.size(), "VEC2");
  const int idx = g.indices({0, 2, 1, 0, 3, 2});
  g.mesh(pos, idx);
  g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = tex;
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  g.doc["materials"] = {{{"name", "bark"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  g.doc["textures"] = {{{"source", 0}}};
  g.doc["images"] = {{{"uri", "bark.png"}}};
  g.node({{"mesh", 0}});
  g.write_gltf(dir, "model");
  expect_missing_texture(dir, "render model.gltf --size 64x48 --out out.png", "bark.png", "bark");
}

TEST(MaterialCli, MaskedTexturedJsonSceneRenders) {
  const fs::path dir = testsupport::temp_dir("material_cli_render");
  fs::create_directories(dir / "leaves");
  {
    std::vector<uint8_t> px;
    for (int r = 0; r < 64; ++r)
      for (int x = 0; x < 64; ++x) {
        const float s = (x + 0.5f) / 64 - 0.5f, t = (r + 0.5f) / 64 - 0.5f;
        px.insert(px.end(), {60, 170, 60, uint8_t(s * s + t * t < 0.16f ? 255 : 0)});
      }
    auto out = OIIO::ImageOutput::create((dir / "leaves/disc.png").string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(64, 64, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open((dir / "leaves/disc.png").string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    ASSERT_TRUE(out->close());
  }
  std::ofstream(dir / "leaf.json") << leaf_json("leaves/disc.png");
  const testsupport::Outcome r = testsupport::shadowlab(dir, "render leaf.json --size 64x48 --out out.png");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.png"));
}
