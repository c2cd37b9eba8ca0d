// sRGB conversion of a colour target and the OpenImageIO PNG writer.
#include "scenes/io/png_frame.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>

#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

namespace {

uint8_t to_byte(float v) {
  v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN -> 0
  return uint8_t(std::nearbyint(v * 255.0f));
}

}  // namespace

std::vector<uint8_t> srgb8_top_first(const raster::ColorTarget& target, bool alpha) {
  const int w = target.width(), h = target.height(), n = alpha ? 4 : 3;
  std::vector<uint8_t> out(size_t(w) * size_t(h) * size_t(n));
  // Linear byte -> sRGB byte, for linear RGBA8 targets.
  std::array<uint8_t, 256> encode{};
  for (int i = 0; i < 256; ++i) encode[size_t(i)] = to_byte(raster::srgb_encode(float(i) / 255.0f));
  for (int r = 0; r < h; ++r) {
    const int y = h - 1 - r;  // file row r is target row h − 1 − r
    uint8_t* dst = out.data() + size_t(r) * size_t(w) * size_t(n);
    for (int x = 0; x < w; ++x, dst += n) {
      if (target.format() == raster::ColorFormat::rgba8) {
        const uint8_t* p = target.row8(y) + size_t(x) * 4;
        for (int c = 0; c < 3; ++c) dst[c] = target.srgb() ? p[c] : encode[p[c]];
        if (alpha) dst[3] = p[3];
      } else {
        const glm::vec4 p = target.read(x, y);  // a float target of fewer channels: missing ones 0, alpha 1
        for (int c = 0; c < 3; ++c) dst[c] = to_byte(raster::srgb_encode(std::isnan(p[c]) ? 0.0f : p[c]));
        if (alpha) dst[3] = to_byte(p[3]);
      }
    }
  }
  return out;
}

void write_png(const std::filesystem::path& path, const raster::ColorTarget& target, bool alpha) {
  WriteBatch batch;
  write_png(batch, path, target, alpha);
  batch.commit();
}

std::vector<unsigned char> encode_png(const raster::ColorTarget& target, bool alpha, const std::filesystem::path& name) {
  const std::vector<uint8_t> pixels = srgb8_top_first(target, alpha);
  std::vector<unsigned char> png;
  OIIO::Filesystem::IOVecOutput proxy(png);
  auto out = OIIO::ImageOutput::create("png");
  if (!out) throw IoError(name, "cannot create a PNG writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(target.width(), target.height(), alpha ? 4 : 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  // GL colour is straight (unassociated) alpha: without this OpenImageIO would divide colour by alpha.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->set_ioproxy(&proxy) || !out->open(name.string(), spec)) throw IoError(name, out->geterror());
  if (!out->write_image(OIIO::TypeDesc::UINT8, pixels.data())) throw IoError(name, out->geterror());
  if (!out->close()) throw IoError(name, out->geterror());
  return png;
}

void write_png(WriteBatch& batch, const std::filesystem::path& path, const raster::ColorTarget& target, bool alpha) {
  // Encoded in memory, then written by write_bytes, which checks every write and the flush: the PNG library's
  // own file writes do not report a full disk.
  const std::vector<unsigned char> png = encode_png(target, alpha, path);
  batch.stage(path, [&](const std::filesystem::path& tmp) { write_bytes(tmp, png.data(), png.size()); });
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
