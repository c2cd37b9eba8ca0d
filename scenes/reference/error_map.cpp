// The error map image (see error_map.h).
#include "scenes/reference/error_map.h"

#include "scenes/reference/occlusion_scene.h"
#include "scenes/reference/shadow_score.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

raster::ColorTarget error_map(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors) {
  if (errors.size() != size_t(frame.width()) * size_t(frame.height()))
    throw ReferenceError("reference: the error mask does not match the frame's size");
  raster::ColorTarget out(frame.width(), frame.height(), raster::ColorFormat::rgba8);
  for (int y = 0; y < frame.height(); ++y)
    for (int x = 0; x < frame.width(); ++x) {
      const uint8_t e = errors[size_t(y) * size_t(frame.width()) + size_t(x)];
      const glm::vec4 f = frame.read(x, y);
      const float grey = 0.15f * (0.2126f * f.r + 0.7152f * f.g + 0.0722f * f.b);
      glm::vec4 c(grey, grey, grey, 1.0f);
      // Pure red, a light blue (pure blue is too dark to find on a dark frame), magenta for both.
      if (e == kFalseShadowed) c = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
      else if (e == kFalseLit) c = glm::vec4(0.1f, 0.45f, 1.0f, 1.0f);
      else if (e) c = glm::vec4(1.0f, 0.0f, 1.0f, 1.0f);
      out.write(x, y, c);
    }
  return out;
}

raster::ColorTarget contact_sheet(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors,
                                  const raster::ColorTarget* extra) {
  const raster::ColorTarget map = error_map(frame, errors);
  if (extra && (extra->width() != frame.width() || extra->height() != frame.height()))
    throw ReferenceError("reference: the contact sheet's third image differs in size from the frame");
  const int w = frame.width();
  raster::ColorTarget out((extra ? 3 : 2) * w, frame.height(), raster::ColorFormat::rgba8);
  for (int y = 0; y < frame.height(); ++y)
    for (int x = 0; x < w; ++x) {
      out.write(x, y, frame.read(x, y));
      out.write(w + x, y, map.read(x, y));
      if (extra) out.write(2 * w + x, y, extra->read(x, y));
    }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace reference
