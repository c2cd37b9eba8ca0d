// sRGB conversion of a colour target and the OpenImageIO PNG writer.
#include "scenes/io/png_frame.h"

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>

#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"

namespace scenes::io {

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
        const float* p = target.row32f(y) + size_t(x) * 4;
        for (int c = 0; c < 3; ++c) dst[c] = to_byte(raster::srgb_encode(std::isnan(p[c]) ? 0.0f : p[c]));
        if (alpha) dst[3] = to_byte(p[3]);
      }
    }
  }
  return out;
}

void write_png(const std::filesystem::path& path, const raster::ColorTarget& target, bool alpha) {
  const std::vector<uint8_t> pixels = srgb8_top_first(target, alpha);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw IoError(tmp, "cannot create a PNG writer: " + OIIO::geterror());
    OIIO::ImageSpec spec(target.width(), target.height(), alpha ? 4 : 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    // GL colour is straight (unassociated) alpha: without this OpenImageIO would divide colour by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(tmp.string(), spec)) throw IoError(tmp, out->geterror());
    if (!out->write_image(OIIO::TypeDesc::UINT8, pixels.data())) throw IoError(tmp, out->geterror());
    if (!out->close()) throw IoError(tmp, out->geterror());
  });
}

}  // namespace scenes::io
