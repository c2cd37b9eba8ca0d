// Reading an image through OpenImageIO into an owned Texture2D.
#include "scenes/io/material_texture.h"
#include "scenes/io/quiet_stderr.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <cstdio>
#include <vector>

#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

namespace {

// Expands n channels (1..4) to RGBA: grey, grey + alpha, RGB, RGBA.
template <class T>
void expand(const T* p, int n, T one, T out[4]) {
  switch (n) {
    case 1: out[0] = out[1] = out[2] = p[0], out[3] = one; break;
    case 2: out[0] = out[1] = out[2] = p[0], out[3] = p[1]; break;
    case 3: out[0] = p[0], out[1] = p[1], out[2] = p[2], out[3] = one; break;
    default: out[0] = p[0], out[1] = p[1], out[2] = p[2], out[3] = p[3]; break;
  }
}

// Straight alpha, as GL texture data is: by default OpenImageIO would premultiply colour by alpha.
OIIO::ImageSpec straight_alpha() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

// CRC-32 of the PNG specification (ISO 3309, reflected polynomial 0xEDB88320), over the bytes.
uint32_t png_crc(std::span<const uint8_t> bytes) {
  static const auto table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1u ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (const uint8_t b : bytes) c = table[(c ^ b) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

// What is wrong with an embedded PNG's chunk structure, or nothing: every chunk (length, type, data, CRC) lies
// within the bytes with a right CRC, up to IEND. Checked before libpng sees the bytes: a PNG that libpng rejects
// part-way leaves error strings unreachable inside OpenImageIO 2.4 (tests/fuzz/lsan.supp), and a cut or damaged
// image named by its chunk is the clearer message.
std::optional<std::string> png_damage(std::span<const uint8_t> bytes) {
  size_t at = 8;  // after the signature
  for (int index = 0;; ++index) {
    if (bytes.size() - at < 12) return "the PNG is cut short before chunk " + std::to_string(index);
    const uint32_t length = uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 |
                            uint32_t(bytes[at + 3]);
    std::string type;
    for (size_t k = 4; k < 8; ++k)
      type += std::isalpha(bytes[at + k]) ? char(bytes[at + k]) : '?';
    const std::string chunk = "chunk " + std::to_string(index) + " ('" + type + "')";
    if (length > bytes.size() - at - 12) return "the PNG is cut short in " + chunk;
    const std::span<const uint8_t> typed = bytes.subspan(at + 4, size_t(length) + 4);
    const size_t c = at + 8 + length;
    const uint32_t stored = uint32_t(bytes[c]) << 24 | uint32_t(bytes[c + 1]) << 16 | uint32_t(bytes[c + 2]) << 8 |
                            uint32_t(bytes[c + 3]);
    if (png_crc(typed) != stored) return "the PNG is damaged: " + chunk + " fails its CRC";
    if (type == "IEND") return std::nullopt;
    at = c + 4;
  }
}

// Reads an opened image into a texture; errors name `path` and begin with `prefix`.
shading::Texture2D read_texture(OIIO::ImageInput& image, const std::filesystem::path& path, const std::string& prefix,
                                const TextureLoadOptions& options) {
  OIIO::ImageInput* in = &image;
  const OIIO::ImageSpec spec = in->spec();
  const int w = spec.width, h = spec.height, n = std::min(spec.nchannels, 4);
  if (w < 1 || h < 1 || w > shading::kMaxTextureSize || h > shading::kMaxTextureSize)
    throw IoError(path, prefix + "image size " + std::to_string(w) + " x " + std::to_string(h) + " is outside 1.." +
                            std::to_string(shading::kMaxTextureSize));
  if (n < 1) throw IoError(path, prefix + "image has no channels");
  const OIIO::TypeDesc fmt = spec.format;
  const bool is8 = fmt.basetype == OIIO::TypeDesc::UINT8 || fmt.basetype == OIIO::TypeDesc::INT8;
  const bool is_half = fmt.basetype == OIIO::TypeDesc::HALF;
  const bool is_int =
      !is8 && !is_half && fmt.basetype != OIIO::TypeDesc::FLOAT && fmt.basetype != OIIO::TypeDesc::DOUBLE;

  shading::TexelFormat tf = shading::TexelFormat::rgba32f;
  if (is8) tf = options.srgb ? shading::TexelFormat::rgba8_srgb : shading::TexelFormat::rgba8;
  if (is_half) tf = shading::TexelFormat::rgba16f;
  shading::Texture2D tex(w, h, tf, false);

  const size_t texels = size_t(w) * size_t(h);
  if (is8) {
    std::vector<uint8_t> px(texels * size_t(n));
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::UINT8, px.data()))
      throw IoError(path, prefix + "cannot read the pixels: " + in->geterror());
    for (int r = 0; r < h; ++r) {
      std::byte* row = tex.mutable_row(0, h - 1 - r);  // file row r is texture row h − 1 − r
      for (int x = 0; x < w; ++x) {
        uint8_t v[4];
        expand(px.data() + (size_t(r) * size_t(w) + size_t(x)) * size_t(n), n, uint8_t(255), v);
        for (int c = 0; c < 4; ++c) row[size_t(x) * 4 + size_t(c)] = std::byte(v[c]);
      }
    }
  } else {
    std::vector<float> px(texels * size_t(n));
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, px.data()))
      throw IoError(path, prefix + "cannot read the pixels: " + in->geterror());
    const bool decode = is_int && options.srgb;
    for (int r = 0; r < h; ++r) {
      for (int x = 0; x < w; ++x) {
        float v[4];
        expand(px.data() + (size_t(r) * size_t(w) + size_t(x)) * size_t(n), n, 1.0f, v);
        if (decode)
          for (int c = 0; c < 3; ++c) v[c] = raster::srgb_decode(v[c]);
        tex.set_texel(x, h - 1 - r, glm::vec4(v[0], v[1], v[2], v[3]));
      }
    }
  }
  in->close();
  if (options.mipmaps) tex.generate_mips();
  return tex;
}

}  // namespace

shading::Texture2D load_texture(const std::filesystem::path& path, const TextureLoadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(path, "no such file");
  const OIIO::ImageSpec config = straight_alpha();
  const QuietStderr quiet;
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw IoError(path, "cannot read the image: " + OIIO::geterror());
  return read_texture(*in, path, "", options);
}

shading::Texture2D load_texture(std::span<const uint8_t> bytes, const std::filesystem::path& file,
                                const std::string& where, const TextureLoadOptions& options) {
  const std::string prefix = where + ": ";
  static constexpr uint8_t kPng[] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  static constexpr uint8_t kJpeg[] = {0xff, 0xd8, 0xff};
  const auto starts = [&](std::span<const uint8_t> magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
  };
  const char* format = starts(kPng) ? "png" : starts(kJpeg) ? "jpeg" : nullptr;
  if (!format) throw IoError(file, prefix + "the embedded image is neither PNG nor JPEG (" +
                                       std::to_string(bytes.size()) + " bytes)");
  if (format == std::string_view("png"))
    if (const auto damage = png_damage(bytes)) throw IoError(file, prefix + "cannot decode the embedded image: " + *damage);
  const OIIO::ImageSpec config = straight_alpha();
  const QuietStderr quiet;
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  auto in = OIIO::ImageInput::create(format, false, &config, &memory);
  OIIO::ImageSpec spec;
  if (!in || !in->set_ioproxy(&memory) || !in->open(file.string(), spec, config)) {
    std::string why = in ? in->geterror() : std::string();
    if (why.empty()) why = OIIO::geterror();
    throw IoError(file, prefix + "cannot decode the embedded " + format + " image" + (why.empty() ? "" : ": " + why));
  }
  return read_texture(*in, file, prefix, options);
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
