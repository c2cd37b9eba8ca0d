// The error map image (see error_map.h).
#include "scenes/reference/error_map.h"

#include "scenes/reference/occlusion_scene.h"
#include "scenes/reference/shadow_score.h"

namespace reference {

raster::ColorTarget error_map(const raster::ColorTarget& frame, const std::vector<uint8_t>& errors) {
  if (errors.size() != size_t(frame.width()) * size_t(frame.height()))
    throw ReferenceError("reference: the error mask does not match the frame's size");
  raster::ColorTarget out(frame.width(), frame.height(), raster::ColorFormat::rgba8);
  for (int y = 0; y < frame.height(); ++y)
    for (int x = 0; x < frame.width(); ++x) {
      const uint8_t e = errors[size_t(y) * size_t(frame.width()) + size_t(x)];
      const glm::vec4 f = frame.read(x, y);
      const float grey = 0.4f * (0.2126f * f.r + 0.7152f * f.g + 0.0722f * f.b);
      glm::vec4 c(grey, grey, grey, 1.0f);
      if (e) c = glm::vec4((e & kFalseShadowed) ? 1.0f : 0.0f, 0.0f, (e & kFalseLit) ? 1.0f : 0.0f, 1.0f);
      out.write(x, y, c);
    }
  return out;
}

}  // namespace reference
