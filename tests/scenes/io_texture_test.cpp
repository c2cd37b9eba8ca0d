// Material textures through OpenImageIO: PNG, JPEG and EXR files land in GL row order (the picture's bottom
// row at t = 0), 8-bit sRGB bytes unchanged, floats and halves kept, channels expanded to RGBA.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <vector>

#include "scenes/io/io_error.h"
#include "scenes/io/material_texture.h"
#include "shading/lookup.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using shading::TexelFormat;

// Writes pixels (top row first, as files hold them, straight alpha) with OpenImageIO.
template <class T>
void write_image(const fs::path& file, int w, int h, int n, OIIO::TypeDesc type, const std::vector<T>& px) {
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(w, h, n, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  ASSERT_TRUE(out->open(file.string(), spec));
  ASSERT_TRUE(out->write_image(type, px.data()));
  ASSERT_TRUE(out->close());
}

TEST(IoTexture, PngLandsInGLRowOrderWithBytesUnchanged) {
  const fs::path dir = testsupport::temp_dir("io_texture_png");
  // 2 × 3 RGBA, file rows top first: row r, column x has red 10·r + x.
  std::vector<uint8_t> px;
  for (int r = 0; r < 3; ++r)
    for (int x = 0; x < 2; ++x) px.insert(px.end(), {uint8_t(10 * r + x), 50, 200, 255});
  write_image(dir / "t.png", 2, 3, 4, OIIO::TypeDesc::UINT8, px);
  const shading::Texture2D t = scenes::io::load_texture(dir / "t.png", {.srgb = true, .mipmaps = false});
  EXPECT_EQ(t.format(), TexelFormat::rgba8_srgb);
  EXPECT_EQ(t.levels(), 1);
  // Texture row j is file row 2 − j: the top-left of the picture is texel (0, 2).
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 2; ++i) EXPECT_EQ(uint8_t(t.level(0).row(j)[i * 4]), uint8_t(10 * (2 - j) + i)) << i << j;
  const shading::Texture2D lin = scenes::io::load_texture(dir / "t.png", {.srgb = false, .mipmaps = true});
  EXPECT_EQ(lin.format(), TexelFormat::rgba8);
  EXPECT_EQ(lin.levels(), 2);
  EXPECT_EQ(shading::texel_fetch(lin, {1, 0}), glm::vec4(21 / 255.0f, 50 / 255.0f, 200 / 255.0f, 1.0f));
}

TEST(IoTexture, GreyAndGreyAlphaExpandToRgba) {
  const fs::path dir = testsupport::temp_dir("io_texture_grey");
  write_image(dir / "g.png", 1, 1, 1, OIIO::TypeDesc::UINT8, std::vector<uint8_t>{90});
  write_image(dir / "ga.png", 1, 1, 2, OIIO::TypeDesc::UINT8, std::vector<uint8_t>{90, 30});
  const auto g = scenes::io::load_texture(dir / "g.png", {.srgb = false, .mipmaps = false});
  EXPECT_EQ(shading::texel_fetch(g, {0, 0}), glm::vec4(90 / 255.0f, 90 / 255.0f, 90 / 255.0f, 1.0f));
  const auto ga = scenes::io::load_texture(dir / "ga.png", {.srgb = false, .mipmaps = false});
  EXPECT_EQ(shading::texel_fetch(ga, {0, 0}), glm::vec4(90 / 255.0f, 90 / 255.0f, 90 / 255.0f, 30 / 255.0f));
}

TEST(IoTexture, ExrFloatAndHalfKeepTheirValues) {
  const fs::path dir = testsupport::temp_dir("io_texture_exr");
  // 1 × 2 RGB float: top row (0.25, −1, 8), bottom row (1.5, 2, 3).
  write_image(dir / "f.exr", 1, 2, 3, OIIO::TypeDesc::FLOAT, std::vector<float>{0.25f, -1.0f, 8.0f, 1.5f, 2.0f, 3.0f});
  const auto f = scenes::io::load_texture(dir / "f.exr", {.srgb = true, .mipmaps = false});
  EXPECT_EQ(f.format(), TexelFormat::rgba32f);
  EXPECT_EQ(shading::texel_fetch(f, {0, 0}), glm::vec4(1.5f, 2.0f, 3.0f, 1.0f));  // floats are never decoded
  EXPECT_EQ(shading::texel_fetch(f, {0, 1}), glm::vec4(0.25f, -1.0f, 8.0f, 1.0f));
  write_image(dir / "h.exr", 1, 1, 4, OIIO::TypeDesc::FLOAT, std::vector<float>{0.5f, 0.125f, 2.0f, 1.0f});
  // OpenImageIO writes FLOAT as asked; ask for half explicitly.
  {
    auto out = OIIO::ImageOutput::create((dir / "half.exr").string());
    OIIO::ImageSpec spec(1, 1, 4, OIIO::TypeDesc::HALF);
    ASSERT_TRUE(out->open((dir / "half.exr").string(), spec));
    const float v[4] = {0.5f, 0.125f, 2.0f, 1.0f};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, v));
    out->close();
  }
  const auto h = scenes::io::load_texture(dir / "half.exr", {.srgb = true, .mipmaps = false});
  EXPECT_EQ(h.format(), TexelFormat::rgba16f);
  EXPECT_EQ(shading::texel_fetch(h, {0, 0}), glm::vec4(0.5f, 0.125f, 2.0f, 1.0f));
}

TEST(IoTexture, JpegLoadsUpsideUp) {
  const fs::path dir = testsupport::temp_dir("io_texture_jpeg");
  // 16 × 16, top half white, bottom half black (flat 8 × 8 blocks survive JPEG almost exactly).
  std::vector<uint8_t> px;
  for (int r = 0; r < 16; ++r)
    for (int x = 0; x < 16; ++x) px.insert(px.end(), 3, uint8_t(r < 8 ? 255 : 0));
  write_image(dir / "j.jpg", 16, 16, 3, OIIO::TypeDesc::UINT8, px);
  const auto j = scenes::io::load_texture(dir / "j.jpg", {.srgb = true, .mipmaps = true});
  EXPECT_EQ(j.format(), TexelFormat::rgba8_srgb);
  EXPECT_LT(shading::texel_fetch(j, {4, 2}).r, 0.02f);   // t near 0: the picture's bottom, black
  EXPECT_GT(shading::texel_fetch(j, {4, 13}).r, 0.98f);  // t near 1: the top, white
  EXPECT_EQ(j.levels(), 5);
}

TEST(IoTexture, MissingOrBrokenFilesThrowIoError) {
  const fs::path dir = testsupport::temp_dir("io_texture_errors");
  try {
    scenes::io::load_texture(dir / "none.png");
    FAIL() << "no exception";
  } catch (const scenes::io::IoError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "none.png").string() + ": no such file");
  }
  {
    std::FILE* f = std::fopen((dir / "junk.png").c_str(), "w");
    std::fputs("junk", f);
    std::fclose(f);
  }
  EXPECT_THROW(scenes::io::load_texture(dir / "junk.png"), scenes::io::IoError);
}

}  // namespace
