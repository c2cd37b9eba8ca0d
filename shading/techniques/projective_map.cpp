// Projective caster maps: mip planning and building (see projective_map.h).
#include "shading/techniques/projective_map.h"

#include <algorithm>
#include <cmath>

#include "shading/techniques/caster_decimate.h"
#include "shading/techniques/masked_depth.h"
#include "shading/techniques/offset_blur.h"
#include "raster/parallel_clear.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

MipPlan plan_mips(int map_size, float lod_bias) {
  const int levels = mip_level_count(std::max(map_size, 1), std::max(map_size, 1));
  int want = lod_bias > 0.0f ? int(std::ceil(std::min(lod_bias, 14.0f))) : 0;
  want = std::min(want, levels - 1);
  for (int level = want; level >= 0; --level) {
    // Level-0 texels reaching the first texel of `level`: going up one level, each texel covers
    // size(l) / size(l + 1) texels of the level above, partly covered ones included whole.
    int ring = 1;
    for (int l = level - 1; l >= 0; --l)
      ring = int(std::ceil(double(ring) * double(mip_size(map_size, l)) / double(mip_size(map_size, l + 1)) - 1e-9));
    if (map_size - 2 * ring >= 1 || level == 0) return MipPlan{ring, level};
  }
  return MipPlan{};
}

CasterMap build_caster_map(raster::Renderer& renderer, const ProjectiveLight& light,
                           const ProjectiveSettings& settings, const Box& bounds, std::span<const CasterPart> parts) {
  CasterMap m;
  const int size = std::max(1, settings.map_size);
  m.mips = plan_mips(size, settings.lod_bias);
  // The offset blur spreads dark texels one texel per pass: the caster is drawn that many texels further in, so
  // the ring the mips need (one texel without them) is still white after the last pass. Passes that would
  // leave no inner texel are given up, as plan_mips gives up levels.
  m.blur_passes = std::clamp(settings.blur_passes, 0, std::max(0, (size - 1) / 2 - m.mips.ring));
  const int ring = m.mips.ring + m.blur_passes;
  m.frustum = fit_caster_frustum(light, bounds, size, ring);
  m.bounds = bounds;
  m.target = std::make_unique<raster::ColorTarget>(size, size, raster::ColorFormat::rgba8);
  raster::clear_on_workers(*m.target, glm::vec4(1.0f), renderer.pool());
  const int inner = size - 2 * ring;
  if (m.frustum.valid && inner >= 1) {
    raster::DrawState s;
    s.depth_test = false;
    s.depth_write = false;
    s.cull = raster::CullMode::none;
    s.scissor = raster::Rect{ring, ring, inner, inner};  // the outer ring stays white
    CasterMaskShader shader;
    shader.view_proj = m.frustum.proj * m.frustum.view;
    // A cell of half a texel: merged vertices move by less than one texel's width.
    const float cell = settings.decimate ? 0.5f * m.frustum.texel_world : 0.0f;
    for (const CasterPart& part : parts) {
      if (part.indices.empty()) continue;
      shader.shade = part.shade;
      if (part.alpha) {  // the alpha test needs every texture coordinate: not decimated
        std::vector<MaskedVertex> vertices(part.positions.size());
        for (size_t i = 0; i < vertices.size(); ++i)
          vertices[i] = {part.positions[i], i < part.texcoords.size() ? part.texcoords[i] : glm::vec2(0.0f)};
        m.triangles += part.indices.size() / 3;
        renderer.draw(raster::RenderTargets{nullptr, m.target.get()}, s, MaskedDepthShader<CasterMaskShader>{shader, part.alpha},
                      std::span<const MaskedVertex>(vertices), std::span<const uint32_t>(part.indices));
        continue;
      }
      const DecimatedMesh mesh = cluster_vertices(part.positions, part.indices, cell);
      if (mesh.indices.empty()) continue;
      m.triangles += mesh.indices.size() / 3;
      renderer.draw(raster::RenderTargets{nullptr, m.target.get()}, s, shader,
                    std::span<const glm::vec3>(mesh.positions), std::span<const uint32_t>(mesh.indices));
    }
  }
  if (m.blur_passes > 0) {
    auto scratch = std::make_unique<raster::ColorTarget>(size, size, raster::ColorFormat::rgba8);
    offset_blur(renderer, m.target, scratch, m.blur_passes, settings.blur_offset);
  }
  m.texture = Texture2D::view(*m.target);
  if (m.mips.max_level > 0) m.texture.generate_mips();
  return m;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
