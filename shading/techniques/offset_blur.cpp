// The offset blur of projective maps (see offset_blur.h): a full-screen shader of four LINEAR lookups.
#include "shading/techniques/offset_blur.h"

#include <stdexcept>
#include <utility>

#include "shading/filter.h"
#include "shading/sampler.h"
#include "shading/techniques/full_screen_pass.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

struct OffsetBlurShader : FullScreenShader<OffsetBlurShader> {
  Texture2D src;  // a view of the source target
  Sampler sampler = Sampler::plain(Filter::linear, Wrap::clamp_to_edge);
  float offset = 0.5f;
  glm::vec2 size{1.0f};
  // textureLod(src, st, 0) on the RGBA8 map: what lookup.h's sample_color computes for one level, without the
  // per-lookup format dispatch and level choice.
  glm::vec4 lookup(glm::vec2 st) const {
    return reduce_color<TexelFormat::rgba8>(footprint_2d(src.level(0), sampler, Filter::linear, st), glm::vec4(0.0f));
  }
  glm::vec4 texel(int x, int y) const {
    // The lookups' coordinates: s = (x + 0.5 ± d) / W, so LINEAR's u = s·W − 0.5 is x ± d (exactly when W is a
    // power of two and d has few bits). Helper lanes past the edge read the clamped edge; they are not written.
    const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
    glm::vec4 sum(0.0f);
    for (const float dy : {-offset, offset})
      for (const float dx : {-offset, offset})
        sum += lookup(glm::vec2((cx + dx) / size.x, (cy + dy) / size.y));
    return sum * 0.25f;
  }
};

}  // namespace

raster::DrawStats offset_blur_pass(raster::Renderer& renderer, const raster::ColorTarget& src,
                                   raster::ColorTarget& dst, float offset) {
  if (&src == &dst) throw std::invalid_argument("offset_blur_pass: source and destination must differ");
  if (src.width() != dst.width() || src.height() != dst.height() || src.format() != dst.format())
    throw std::invalid_argument("offset_blur_pass: source and destination must have the same size and format");
  if (src.format() != raster::ColorFormat::rgba8 || src.srgb())
    throw std::invalid_argument("offset_blur_pass: the maps are linear RGBA8 targets");
  if (!(offset > 0.0f && offset <= kMaxBlurOffset))
    throw std::invalid_argument("offset_blur_pass: the offset must lie in (0, 1] texels");
  OffsetBlurShader s;
  s.src = Texture2D::view(src);
  s.offset = offset;
  s.size = glm::vec2(float(src.width()), float(src.height()));
  return draw_full_screen(renderer, dst, s);
}

raster::DrawStats offset_blur(raster::Renderer& renderer, std::unique_ptr<raster::ColorTarget>& map,
                              std::unique_ptr<raster::ColorTarget>& scratch, int passes, float offset) {
  raster::DrawStats stats;
  for (int k = 0; k < passes; ++k) {
    stats += offset_blur_pass(renderer, *map, *scratch, offset);
    std::swap(map, scratch);
  }
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
