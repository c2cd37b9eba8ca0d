// SurfaceRecord's storage and its conversion to EXR channels (see surface_record.h).
#include "scenes/frame/surface_record.h"

#include <iterator>
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

SurfaceRecord::SurfaceRecord(int w, int h, size_t light_count)
    : width(w),
      height(h),
      lights(light_count),
      covered(pixels(), 0),
      position(pixels(), glm::vec3(0.0f)),
      normal(pixels(), glm::vec3(0.0f)),
      depth(pixels(), 1.0f),  // the cleared depth (CONVENTIONS.md) where nothing is drawn, as in a depth buffer
      lit_facing(pixels() * light_count, 0),
      visibility(pixels() * light_count, 1.0f) {}

std::optional<AovChannel> parse_aov_channel(std::string_view name) {
  for (size_t i = 0; i < std::size(kAovNames); ++i)
    if (name == kAovNames[i]) return AovChannel(i);
  return std::nullopt;
}

scenes::io::ExrImage aov_image(const SurfaceRecord& r, const std::vector<AovChannel>& channels) {
  scenes::io::ExrImage img{r.width, r.height, {}};
  const size_t n = r.pixels();
  auto add = [&](std::string name, auto value) {
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = value(i);
    img.channels.push_back({std::move(name), std::move(v)});
  };
  for (AovChannel c : channels) {
    switch (c) {
      case AovChannel::position:
        for (int k = 0; k < 3; ++k) add(std::string("P.") + "XYZ"[k], [&](size_t i) { return r.position[i][k]; });
        break;
      case AovChannel::normal:
        for (int k = 0; k < 3; ++k) add(std::string("N.") + "XYZ"[k], [&](size_t i) { return r.normal[i][k]; });
        break;
      case AovChannel::depth: add("Z", [&](size_t i) { return r.depth[i]; }); break;
      case AovChannel::visibility:
        for (size_t l = 0; l < r.lights; ++l) {
          const std::string light = "light" + std::to_string(l);
          add(light + ".V", [&](size_t i) { return r.visibility[i * r.lights + l]; });
          add(light + ".facing", [&](size_t i) { return float(r.lit_facing[i * r.lights + l]); });
        }
        break;
    }
  }
  add("A", [&](size_t i) { return float(r.covered[i]); });
  return img;
}

SHADOWLAB_ISA_END
}  // namespace frame
