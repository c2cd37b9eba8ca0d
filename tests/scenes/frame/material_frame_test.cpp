// glTF-style materials in whole frames: an alpha-masked leaf card (a quad whose texture's alpha is a disc)
// casts a disc-shaped shadow in every technique's depth passes, measured as the shadowed floor area against the
// analytic one; a textured quad shows its texture upright and sRGB-decoded in the camera pass; masked frames are
// bit-identical at any thread count; images embedded in glTF files (a GLB's buffer view, a data: URI) cast the same
// shadow as the file they were read from. The textures are PNG files the tests write.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "raster/target.h"
#include "scenes/frame/frame.h"
#include "scenes/gltf_import.h"
#include "scenes/io/io_error.h"
#include "scenes/io/scene_textures.h"
#include "scenes/scene_error.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
namespace tech = shading::tech;

// Writes an RGBA8 PNG, pixel(x, row) giving the bytes of file row `row` (0 = top, as a viewer shows it).
template <class Pixel>
void write_png(const fs::path& file, int w, int h, Pixel&& pixel) {
  std::vector<uint8_t> px;
  for (int r = 0; r < h; ++r)
    for (int x = 0; x < w; ++x) {
      const std::array<uint8_t, 4> p = pixel(x, r);
      px.insert(px.end(), p.begin(), p.end());
    }
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  ASSERT_TRUE(out->open(file.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  ASSERT_TRUE(out->close());
}

// The leaf's alpha: opaque inside the disc of radius 0.4 around (0.5, 0.5) in texture coordinates, clear outside.
constexpr float kDiscRadius = 0.4f;
fs::path disc_texture(const std::string& name) {
  const fs::path file = testsupport::temp_dir(name) / "disc.png";
  constexpr int kSize = 256;
  write_png(file, kSize, kSize, [](int x, int r) {
    const float s = (float(x) + 0.5f) / kSize - 0.5f, t = (float(r) + 0.5f) / kSize - 0.5f;
    const bool in = s * s + t * t <= kDiscRadius * kDiscRadius;
    return std::array<uint8_t, 4>{40, 160, 40, uint8_t(in ? 255 : 0)};
  });
  return file;
}

// A parallelogram a, b, c = b + d − a, d (counter-clockwise seen from its front) as n × n cells, texture
// coordinates (0, 0), (1, 0), (1, 1), (0, 1) at the corners. Cells, not one quad: the dual paraboloid warps
// each triangle's interior linearly, so a large triangle's edges land bowed in its map (paraboloid.h).
scenes::Mesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t n = 1) {
  (void)c;
  scenes::Mesh m;
  m.name = "quad";
  const glm::vec3 normal = glm::normalize(glm::cross(b - a, d - a));
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) {
      const float u = float(i) / float(n), v = float(j) / float(n);
      m.positions.push_back(a + u * (b - a) + v * (d - a));
      m.normals.push_back(normal);
      m.texcoords.push_back({u, v});
    }
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t k = j * (n + 1) + i;
      m.indices.insert(m.indices.end(), {k, k + 1, k + n + 2, k, k + n + 2, k + n + 1});
    }
  return m;
}

constexpr float kLeafHeight = 2.0f, kLeafHalf = 1.0f;
const glm::vec3 kLampPosition{6.0f, 6.0f, 0.0f};
const glm::vec3 kSunDirection = glm::normalize(glm::vec3(-1.5f, -1.0f, 0.0f));

// The shadow of the leaf's disc on the floor (y = 0): its centre and its scale (1 for the sun's parallel
// projection; H / (H − h) for the lamp's central one).
struct Expected {
  glm::vec3 centre;
  float scale;
  float area(float radius) const { return std::numbers::pi_v<float> * radius * radius * scale * scale; }
};
Expected expected_shadow(tech::LightType type) {
  if (type == tech::LightType::directional)
    return {glm::vec3(0, kLeafHeight, 0) + kSunDirection * (kLeafHeight / -kSunDirection.y), 1.0f};
  const float k = kLampPosition.y / (kLampPosition.y - kLeafHeight);
  return {kLampPosition + (glm::vec3(0, kLeafHeight, 0) - kLampPosition) * k, k};
}

// A floor (receives, casts nothing), a horizontal leaf card 2 m up (casts, receives nothing) with the disc
// texture and `mode`, one light of `type` with `technique`, and an orthographic camera looking straight down at
// where the leaf's shadow falls (the leaf itself out of view), 480 × 480 pixels over 3.6 m.
constexpr float kViewHalf = 1.8f;
constexpr int kPixels = 480;
scenes::Scene leaf_scene(const fs::path& texture, scenes::AlphaMode mode, tech::LightType type, tech::Technique technique) {
  scenes::Scene s;
  s.name = "leaf";
  s.objects = {"floor", "leaf"};
  s.meshes.push_back(quad({-8, 0, 8}, {8, 0, 8}, {8, 0, -8}, {-8, 0, -8}));
  s.meshes.push_back(quad({-kLeafHalf, kLeafHeight, kLeafHalf}, {kLeafHalf, kLeafHeight, kLeafHalf},
                          {kLeafHalf, kLeafHeight, -kLeafHalf}, {-kLeafHalf, kLeafHeight, -kLeafHalf}, 16));
  scenes::Material floor;
  floor.name = "floor";
  scenes::Material leaf;
  leaf.name = "leaf";
  leaf.texture = texture.string();
  leaf.alpha_mode = mode;
  leaf.double_sided = true;
  s.materials = {floor, leaf};
  scenes::Instance f{"floor", 0, 0, 0, glm::mat4(1.0f), false, true};
  scenes::Instance l{"leaf", 1, 1, 1, glm::mat4(1.0f), true, false};
  s.instances = {f, l};

  const Expected e = expected_shadow(type);
  scenes::Camera cam;
  cam.position = e.centre + glm::vec3(0, 10, 0);
  cam.target = e.centre;
  cam.up = {0, 0, -1};
  cam.projection = scenes::Orthographic{-kViewHalf, kViewHalf, -kViewHalf, kViewHalf, 1.0f, 20.0f};
  s.cameras = {cam};

  scenes::Light light;
  light.name = "light";
  light.type = type;
  light.range = 30.0f;
  if (type == tech::LightType::directional) {
    light.direction = kSunDirection;
  } else {
    light.position = kLampPosition;
    light.direction = type == tech::LightType::hemispherical ? glm::vec3(0, -1, 0) : glm::normalize(e.centre - kLampPosition);
    light.inner_cone_deg = 20.0f, light.outer_cone_deg = 25.0f;
  }
  light.shadow = scenes::default_shadow_settings(type);
  light.shadow.technique = technique;
  light.shadow.map_size = 2048;
  light.shadow.cull_front = false;  // the leaf is one sheet: its front faces must enter the map
  // The filterable maps unblurred and without mips: their blur moves a hard edge by up to its radius, whatever
  // the caster, and so does a coarser level where a pixel covers several texels of the 2048² map (ESM's edge
  // moves towards the shadow).
  // (Cascades and the cube take these keys for their `moments` kind, which is none here: there they would do
  // nothing, which is refused.)
  const bool filterable = tech::find_param(technique, "blur_radius") && !tech::find_param(technique, "moments");
  if (filterable) light.shadow.params["blur_radius"] = 0.0;
  if (filterable) light.shadow.params["moment_mips"] = std::string("none");
  s.lights = {light};
  return s;
}

std::vector<uint8_t> file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string base64(const std::vector<uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
    out += kDigits[n >> 18 & 63];
    out += kDigits[n >> 12 & 63];
    out += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

// A glTF quad whose one material, "leaf" (MASK), takes its base-colour texture from image 0, given by `image`
// (its uri or bufferView and mimeType).
testsupport::GltfFixture embedded_leaf(nlohmann::json image) {
  testsupport::GltfFixture g;
  const int pos = g.positions({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
  g.mesh(pos, g.indices({0, 2, 1, 0, 3, 2}));
  const std::vector<glm::vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // the file's own, unused by leaf_scene_with
  g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = g.accessor(uv.data(), sizeof(glm::vec2) * 4, 5126, 4, "VEC2");
  g.doc["meshes"][0]["primitives"][0]["material"] = 0;
  g.doc["materials"] = {{{"name", "leaf"},
                         {"alphaMode", "MASK"},
                         {"doubleSided", true},
                         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  g.doc["textures"] = {{{"source", 0}}};
  g.doc["images"] = nlohmann::json::array({std::move(image)});
  g.node({{"mesh", 0}});
  return g;
}

// The leaf scene with its leaf material replaced by a glTF file's (texture and all).
scenes::Scene leaf_scene_with(const scenes::Material& imported) {
  scenes::Scene s = leaf_scene("", scenes::AlphaMode::mask, tech::LightType::directional, tech::Technique::shadowmap);
  s.materials[1] = imported;
  return s;
}

frame::FrameConfig view_config() {
  frame::FrameConfig c;
  c.width = c.height = kPixels;
  c.surface_record = true;
  return c;
}

// The floor area the frame shows shadowed (visibility below one half), in square metres.
float shadowed_area(const frame::Frame& f) {
  const frame::SurfaceRecord& r = *f.surface;
  size_t n = 0;
  for (size_t p = 0; p < r.pixels(); ++p)
    if (r.covered[p] && std::abs(r.position[p].y) < 1e-3f && r.lit_facing[p] && r.visibility[p] < 0.5f) ++n;
  const float pixel = 2.0f * kViewHalf / float(kPixels);
  return float(n) * pixel * pixel;
}

}  // namespace

// Every technique draws the masked leaf through its alpha test: the shadow is the disc (area within 1 % of
// π r² k²), not the card's square; the same card opaque casts the square (the count itself is right). Without
// the alpha test in the depth passes every technique casts the square, as the opaque card does (4 k², twice
// the disc's area).
TEST(MaterialFrame, MaskedLeafCastsItsMaskShapeInEveryTechnique) {
  const fs::path tex = disc_texture("material_leaf");
  raster::Renderer renderer(testsupport::test_threads());
  size_t tried = 0;
  for (const tech::TechniqueImpl& impl : tech::registry()) {
    if (impl.application == tech::Application::none) continue;  // every technique that casts a shadow
    const tech::TechniqueInfo& info = tech::info(impl.id);
    for (tech::LightType type : {tech::LightType::directional, tech::LightType::spot, tech::LightType::point,
                                 tech::LightType::hemispherical}) {
      if (!(info.lights & tech::light_bit(type))) continue;
      const Expected e = expected_shadow(type);
      const std::string what = std::string(info.name) + " / " + std::string(tech::to_string(type));
      const float masked = shadowed_area(frame::render_frame(
          leaf_scene(tex, scenes::AlphaMode::mask, type, impl.id), view_config(), renderer));
      EXPECT_NEAR(masked, e.area(2.0f * kLeafHalf * kDiscRadius), 0.01f * e.area(2.0f * kLeafHalf * kDiscRadius))
          << what;
      const float card = 2.0f * kLeafHalf * e.scale;
      const float opaque = shadowed_area(frame::render_frame(
          leaf_scene(tex, scenes::AlphaMode::opaque, type, impl.id), view_config(), renderer));
      EXPECT_NEAR(opaque, card * card, 0.01f * card * card) << what << " (opaque card)";
      // The relative errors, in the XML report (--gtest_output=xml): masked disc, opaque card.
      ::testing::Test::RecordProperty(what, std::to_string(masked / e.area(2.0f * kLeafHalf * kDiscRadius) - 1.0f) +
                                                " " + std::to_string(opaque / (card * card) - 1.0f));
      ++tried;
    }
  }
  EXPECT_GE(tried, 15u);
}

// BLEND is drawn as MASK at 0.5 (scene.h, docs/scene-format.md): the same disc.
TEST(MaterialFrame, BlendCastsAsMaskAtOneHalf) {
  const fs::path tex = disc_texture("material_blend");
  raster::Renderer renderer(testsupport::test_threads());
  const Expected e = expected_shadow(tech::LightType::directional);
  const float area = e.area(2.0f * kLeafHalf * kDiscRadius);
  scenes::Scene s = leaf_scene(tex, scenes::AlphaMode::blend, tech::LightType::directional, tech::Technique::shadowmap);
  s.materials[1].alpha_cutoff = 0.99f;  // ignored by blend
  EXPECT_NEAR(shadowed_area(frame::render_frame(s, view_config(), renderer)), area, 0.01f * area);
}

// The alpha test runs in the camera pass too: looking down on the leaf itself, the floor shows through outside
// the disc. The leaf covers the disc's area of the view (within 1 %).
TEST(MaterialFrame, MaskedLeafIsDiscShapedInTheCameraPass) {
  const fs::path tex = disc_texture("material_leaf_camera");
  raster::Renderer renderer(testsupport::test_threads());
  scenes::Scene s = leaf_scene(tex, scenes::AlphaMode::mask, tech::LightType::directional, tech::Technique::none);
  s.cameras[0].position = {0, 10, 0};
  s.cameras[0].target = {0, 0, 0};
  const frame::Frame f = frame::render_frame(s, view_config(), renderer);
  size_t leaf = 0;
  for (size_t p = 0; p < f.surface->pixels(); ++p) leaf += f.surface->covered[p] && f.surface->position[p].y > 1.0f;
  const float pixel = 2.0f * kViewHalf / float(kPixels);
  const float r = 2.0f * kLeafHalf * kDiscRadius, area = std::numbers::pi_v<float> * r * r;
  EXPECT_NEAR(float(leaf) * pixel * pixel, area, 0.01f * area);
}

// Masked frames (camera pass and depth passes) are bit-identical at 0, 1, 2 and 7 threads, for the classic map
// and the cube map.
TEST(MaterialFrame, MaskedFramesAreBitIdenticalAtAnyThreadCount) {
  const fs::path tex = disc_texture("material_threads");
  for (auto [type, t] : {std::pair{tech::LightType::directional, tech::Technique::shadowmap},
                         std::pair{tech::LightType::point, tech::Technique::cube}}) {
    scenes::Scene s = leaf_scene(tex, scenes::AlphaMode::mask, type, t);
    s.cameras[0].position = {-1, 8, 3};  // the leaf and its shadow both in view
    s.cameras[0].target = expected_shadow(type).centre * 0.5f;
    s.cameras[0].projection = scenes::Perspective{60.0f, std::nullopt, 0.5f, 40.0f};
    s.cameras[0].up = {0, 1, 0};
    s.lights[0].shadow.map_size = 512;
    frame::FrameConfig c = view_config();
    c.width = 160, c.height = 120;
    const scenes::io::SceneTextures textures = scenes::io::load_scene_textures(s);
    raster::Renderer r0(0);
    const frame::Frame base = frame::render_frame(s, c, r0, nullptr, &textures);
    for (int threads : {1, 2, 7}) {
      raster::Renderer r(threads);
      const frame::Frame f = frame::render_frame(s, c, r, nullptr, &textures);
      bool same = true;
      for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) same = same && f.color.read(x, y) == base.color.read(x, y);
      EXPECT_TRUE(same) << threads << " threads";
      EXPECT_EQ(f.surface->visibility, base.surface->visibility) << threads << " threads";
    }
  }
}

// A textured quad facing the camera shows its texture upright (the file's top-left block at the frame's
// top-left) and sRGB-decoded: each block's pixels equal those of the same quad with a flat base colour of the
// block's decoded colour, times the base-colour factor. Compared in the camera pass's radiance, before the
// picture's metered exposure (which differs between the four-coloured card and a one-coloured one).
TEST(MaterialFrame, TexturedQuadShowsItsTextureUprightAndDecoded) {
  const fs::path file = testsupport::temp_dir("material_textured") / "blocks.png";
  // 2 × 2 blocks of 16 × 16 texels, file rows top first: top-left, top-right, bottom-left, bottom-right.
  const std::array<std::array<uint8_t, 3>, 4> blocks{{{200, 40, 40}, {40, 200, 40}, {40, 40, 200}, {128, 128, 128}}};
  write_png(file, 32, 32, [&](int x, int r) {
    const auto& b = blocks[size_t((r / 16) * 2 + x / 16)];
    return std::array<uint8_t, 4>{b[0], b[1], b[2], 255};
  });
  const glm::vec4 factor(0.5f, 1.0f, 1.0f, 1.0f);
  auto scene = [&](const std::string& texture, glm::vec4 base) {
    scenes::Scene s;
    s.name = "textured";
    s.objects = {"card"};
    s.meshes.push_back(quad({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}));
    scenes::Material m;
    m.name = "card";
    m.texture = texture;
    m.base_color = base;
    m.specular_strength = 0.0f;
    s.materials = {m};
    s.instances = {scenes::Instance{"card", 0, 0, 0, glm::mat4(1.0f), true, true}};
    scenes::Camera cam;
    cam.position = {0, 0, 5};
    cam.projection = scenes::Orthographic{-1, 1, -1, 1, 1, 10};
    s.cameras = {cam};
    scenes::Light l;
    l.direction = {0, 0, -1};
    l.intensity = 0.5f;
    l.shadow.technique = tech::Technique::none;
    s.lights = {l};
    return s;
  };
  frame::FrameConfig c;
  c.width = c.height = 64;
  raster::Renderer renderer(testsupport::test_threads());
  const frame::Frame textured = frame::render_frame(scene(file.string(), factor), c, renderer);
  // Block centres in the frame (GL rows, y up): the file's top row of blocks is the frame's upper half.
  const std::array<glm::ivec2, 4> centre{{{16, 48}, {48, 48}, {16, 16}, {48, 16}}};
  for (size_t b = 0; b < 4; ++b) {
    const glm::vec4 decoded(raster::srgb_decode(blocks[b][0] / 255.0f), raster::srgb_decode(blocks[b][1] / 255.0f),
                            raster::srgb_decode(blocks[b][2] / 255.0f), 1.0f);
    const frame::Frame flat = frame::render_frame(scene("", factor * decoded), c, renderer);
    for (int dy = -4; dy <= 4; dy += 4)
      for (int dx = -4; dx <= 4; dx += 4) {
        const int x = centre[b].x + dx, y = centre[b].y + dy;
        EXPECT_EQ(textured.radiance.read(x, y), flat.radiance.read(x, y)) << "block " << b << " at " << x << "," << y;
      }
  }
}

// A texture that does not exist fails the frame before anything is drawn, naming the file and the material.
TEST(MaterialFrame, MissingTextureNamesFileAndMaterial) {
  const fs::path missing = testsupport::temp_dir("material_missing") / "nowhere.png";
  scenes::Scene s = leaf_scene(missing, scenes::AlphaMode::mask, tech::LightType::directional, tech::Technique::shadowmap);
  raster::Renderer renderer(0);
  try {
    frame::render_frame(s, view_config(), renderer);
    FAIL() << "no error";
  } catch (const scenes::io::IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
    EXPECT_NE(what.find("material 'leaf'"), std::string::npos) << what;
    EXPECT_NE(what.find("no such file"), std::string::npos) << what;
  }
}

// An image a glTF file embeds, in a GLB's buffer view or as a data: URI, is decoded like a file: the masked leaf
// casts exactly the shadow it casts with the PNG file those bytes came from (visibility equal at every pixel,
// the disc's area within 1 %). Before embedded images were decoded the leaf had no texture and cast its square.
TEST(MaterialFrame, EmbeddedImagesCastTheSameShadowAsTheirFile) {
  const fs::path dir = testsupport::temp_dir("material_embedded");
  const fs::path png = disc_texture("material_embedded_png");
  const std::vector<uint8_t> bytes = file_bytes(png);
  ASSERT_GT(bytes.size(), 100u);
  raster::Renderer renderer(testsupport::test_threads());
  const frame::Frame reference = frame::render_frame(
      leaf_scene(png, scenes::AlphaMode::mask, tech::LightType::directional, tech::Technique::shadowmap),
      view_config(), renderer);

  testsupport::GltfFixture glb = embedded_leaf({{"mimeType", "image/png"}});
  glb.doc["images"][0]["bufferView"] = glb.buffer_view(bytes.data(), bytes.size());
  const fs::path glb_file = glb.write_glb(dir, "leaf");
  const fs::path uri_file = embedded_leaf({{"uri", "data:image/png;base64," + base64(bytes)}}).write_gltf(dir, "uri");
  for (const fs::path& file : {glb_file, uri_file}) {
    const scenes::Scene imported = scenes::import_gltf(file);
    ASSERT_EQ(imported.materials.size(), 1u);
    const scenes::Material& m = imported.materials[0];
    ASSERT_TRUE(m.embedded_texture) << file;
    EXPECT_EQ(m.embedded_texture.image->bytes, bytes) << file;
    EXPECT_EQ(m.texture, file.string() + "#images[0]");
    EXPECT_TRUE(imported.warnings.empty()) << imported.warnings.front();
    const frame::Frame f = frame::render_frame(leaf_scene_with(m), view_config(), renderer);
    EXPECT_EQ(f.surface->visibility, reference.surface->visibility) << file;
    const float disc = expected_shadow(tech::LightType::directional).area(2.0f * kLeafHalf * kDiscRadius);
    EXPECT_NEAR(shadowed_area(f), disc, 0.01f * disc) << file;
  }
}

// Embedded bytes that are not a PNG or JPEG, a PNG cut short or one with a damaged chunk fail the frame before
// anything is drawn, naming the glTF file, the image's place in it and the material; a buffer view past its buffer fails the import,
// naming the view.
TEST(MaterialFrame, BrokenEmbeddedImagesNameFileImageAndMaterial) {
  const fs::path dir = testsupport::temp_dir("material_embedded_broken");
  const std::vector<uint8_t> png = file_bytes(disc_texture("material_embedded_broken_png"));
  const std::string text = "no image here";
  std::vector<uint8_t> damaged = png;
  damaged[40] ^= 0x5a;  // inside IHDR's or the first data chunk's bytes: its CRC no longer matches
  const std::vector<std::pair<std::vector<uint8_t>, std::string>> cases{
      {std::vector<uint8_t>(text.begin(), text.end()), "neither PNG nor JPEG"},
      {std::vector<uint8_t>(png.begin(), png.begin() + 60), "the PNG is cut short"},
      {damaged, "fails its CRC"}};
  raster::Renderer renderer(0);
  for (const auto& [bytes, reason] : cases) {
    testsupport::GltfFixture g = embedded_leaf({{"mimeType", "image/png"}});
    g.doc["images"][0]["bufferView"] = g.buffer_view(bytes.data(), bytes.size());
    const fs::path file = g.write_glb(dir, "broken");
    const scenes::Scene imported = scenes::import_gltf(file);
    try {
      frame::render_frame(leaf_scene_with(imported.materials[0]), view_config(), renderer);
      FAIL() << "no error for " << reason;
    } catch (const scenes::io::IoError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;
      EXPECT_NE(what.find("material 'leaf'"), std::string::npos) << what;
      EXPECT_NE(what.find("images[0]"), std::string::npos) << what;
      EXPECT_NE(what.find(reason), std::string::npos) << what;
    }
  }
  testsupport::GltfFixture g = embedded_leaf({{"mimeType", "image/png"}});
  const int view = g.buffer_view(png.data(), png.size());
  g.doc["images"][0]["bufferView"] = view;
  g.doc["bufferViews"][size_t(view)]["byteLength"] = png.size() + 4096;
  try {
    scenes::import_gltf(g.write_glb(dir, "past_end"));
    FAIL() << "no error for a view past its buffer";
  } catch (const scenes::SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bufferViews[" + std::to_string(view) + "]"), std::string::npos) << what;
  }
}

// A glTF material as glTF gives it: alphaMode MASK with its cutoff, the base-colour texture read through the
// TEXCOORD_n its texCoord names (v turned into t = 1 − v) and KHR_texture_transform taken into (s, t).
TEST(MaterialFrame, GltfMaterialImportsMaskTexCoordAndTransform) {
  const fs::path dir = testsupport::temp_dir("material_gltf");
  testsupport::GltfFixture g;
  const int pos = g.positions({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
  const std::vector<glm::vec2> uv0{{9, 9}, {9, 9}, {9, 9}, {9, 9}}, uv1{{0.2f, 0.3f}, {1, 0}, {1, 1}, {0, 1}};
  const int t0 = g.accessor(uv0.data(), uv0.size() * sizeof(glm::vec2), 5126, uv0.size(), "VEC2");
  const int t1 = g.accessor(uv1.data(), uv1.size() * sizeof(glm::vec2), 5126, uv1.size(), "VEC2");
  g.mesh(pos, g.indices({0, 2, 1, 0, 3, 2}));
  auto& prim = g.doc["meshes"][0]["primitives"][0];
  prim["attributes"]["TEXCOORD_0"] = t0;
  prim["attributes"]["TEXCOORD_1"] = t1;
  prim["material"] = 0;
  g.doc["materials"] = {{{"name", "leaf"},
                         {"alphaMode", "MASK"},
                         {"alphaCutoff", 0.25},
                         {"pbrMetallicRoughness",
                          {{"baseColorTexture",
                            {{"index", 0},
                             {"texCoord", 1},
                             {"extensions",
                              {{"KHR_texture_transform", {{"offset", {0.5, 0.0}}, {"scale", {0.5, 0.5}}}}}}}}}}}};
  g.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  g.doc["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};
  g.doc["images"] = {{{"uri", "leaf.png"}}};
  g.node({{"mesh", 0}});
  const scenes::Scene s = scenes::import_gltf(g.write_gltf(dir, "leaf"));
  ASSERT_EQ(s.materials.size(), 1u);
  const scenes::Material& m = s.materials[0];
  EXPECT_EQ(m.alpha_mode, scenes::AlphaMode::mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.25f);
  EXPECT_EQ(m.wrap_s, scenes::TextureWrap::clamp_to_edge);
  EXPECT_EQ(m.wrap_t, scenes::TextureWrap::mirrored_repeat);
  EXPECT_EQ(fs::path(m.texture).filename(), "leaf.png");
  ASSERT_EQ(s.meshes[0].texcoords.size(), 4u);
  EXPECT_EQ(s.meshes[0].texcoords[0], glm::vec2(0.2f, 1.0f - 0.3f));  // TEXCOORD_1, v flipped
  // glTF: (0.2, 0.3) -> offset + scale · uv = (0.6, 0.15); in (s, t): (0.6, 0.85).
  const glm::vec3 st = m.texture_transform * glm::vec3(s.meshes[0].texcoords[0], 1.0f);
  EXPECT_NEAR(st.x, 0.6f, 1e-6f);
  EXPECT_NEAR(st.y, 0.85f, 1e-6f);
}

// The irregular z-buffer shades the camera's own samples, found by a pre-pass (camera_surface.h) that must
// alpha-test masked materials as the camera pass does: looking straight down through the leaf's cut-out corners
// at a floor shadowed by an opaque plate below the leaf (the leaf itself lies in sunlight), every floor pixel seen
// through the cut-outs is in the plate's shadow. A pre-pass that drew the card whole would test the leaf's
// sunlit points instead and light them all.
TEST(MaterialFrame, IrregularSeesThroughMaskedReceivers) {
  const fs::path tex = disc_texture("material_irregular_receiver");
  raster::Renderer renderer(testsupport::test_threads());
  scenes::Scene s = leaf_scene(tex, scenes::AlphaMode::mask, tech::LightType::directional, tech::Technique::irregular);
  // The plate at y = 1 over x in [1.5, 3.5]: its shadow on the floor, shifted by 1.5 m against the sun's x,
  // covers x in [0, 2] (z in [-2, 2]); the leaf's disc shadow falls near x = -3, out of view.
  s.objects.push_back("plate");
  s.meshes.push_back(quad({1.5f, 1.0f, 2.0f}, {3.5f, 1.0f, 2.0f}, {3.5f, 1.0f, -2.0f}, {1.5f, 1.0f, -2.0f}, 4));
  scenes::Material plate;
  plate.name = "plate";
  plate.double_sided = true;
  s.materials.push_back(plate);
  s.instances.push_back(scenes::Instance{"plate", 2, 2, 2, glm::mat4(1.0f), true, false});
  s.cameras[0].position = {0, 10, 0};
  s.cameras[0].target = {0, 0, 0};
  const frame::Frame f = frame::render_frame(s, view_config(), renderer);
  const frame::SurfaceRecord& r = *f.surface;
  size_t through = 0, lit = 0;
  for (size_t p = 0; p < r.pixels(); ++p) {
    const glm::vec3 q = r.position[p];
    // Floor pixels under the card (seen through its cut-outs), well inside the plate's shadow (x in [0.1, 0.9]).
    if (!r.covered[p] || std::abs(q.y) > 1e-3f || q.x < 0.1f || q.x > 0.9f || std::abs(q.z) > 0.9f) continue;
    ++through;
    lit += r.visibility[p] >= 0.5f;
  }
  EXPECT_GT(through, 1000u);  // the cut-out corners show this much floor at 480² over 3.6 m
  EXPECT_EQ(lit, 0u) << "of " << through << " floor pixels seen through the leaf's cut-outs";
}
