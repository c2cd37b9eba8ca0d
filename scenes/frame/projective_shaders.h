// How the camera pass applies projective maps to a receiver (the article's two ways), over any camera shader
// `Base` whose varyings carry the world position (`world`):
//   multipass:   Base's draw, then one more draw per overlapping caster with ApplyShader<Base>: the same vertex
//                stage (so the depth is bit-identical and the test is EQUAL, writes off), the map through
//                texgen with clamped coordinates, and multiplicative blending (GL's DST_COLOR, ZERO), scissored
//                to the window rectangle the caster's shadow can reach on the receiver;
//   single-pass: SinglePassShader<Base>: Base's shading and up to N maps multiplied in one fragment shader,
//                one float product per map in the blend's order, so it reproduces the multipass image on the
//                frame's float target exactly; overlaps beyond N fall back to extra passes.
// A receiver that overlaps no caster is drawn once, with Base alone. With a SurfaceRecord, both ways multiply
// each map's factor into the record's visibility of the caster's light at the pixels they draw (the depth test
// runs before the fragment shader, so these are exactly the pixels the blend darkens).
#pragma once
#include <algorithm>
#include <array>
#include <span>

#include "scenes/frame/frame_projective.h"
#include "scenes/frame/surface_record.h"
#include "raster/renderer.h"
#include "shading/techniques/projective_lookup.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

template <class Varyings>
shading::Quad<glm::vec3> world_positions(const raster::QuadIn<Varyings>& q) {
  return {q.in[0].world, q.in[1].world, q.in[2].world, q.in[3].world};
}

// One map's factors into the record, on the quad's drawn (live) lanes.
template <class Varyings>
void record_factors(SurfaceRecord& record, const raster::QuadIn<Varyings>& q, const shading::Quad<float>& f,
                    size_t light) {
  for (size_t l = 0; l < 4; ++l)
    if ((q.live >> l) & 1u) record.multiply_visibility(q.frag_coord[l].x, q.frag_coord[l].y, light, f[l]);
}

// One caster's map as a multiplicative pass: colour = the shadow factor.
template <class Base>
struct ApplyShader {
  using Vertex = typename Base::Vertex;
  using Varyings = typename Base::Varyings;
  Base base;  // for its vertex stage only
  const shading::tech::ProjectiveReader* reader = nullptr;
  SurfaceRecord* record = nullptr;  // optional: the factor goes into light `light`'s visibility
  size_t light = 0;

  glm::vec4 vertex(const Vertex& v, Varyings& out) const { return base.vertex(v, out); }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    const shading::Quad<float> f = shading::tech::projective_factors(*reader, world_positions(q));
    for (size_t l = 0; l < 4; ++l) out.color[l] = glm::vec4(f[l], f[l], f[l], 1.0f);
    if (record) record_factors(*record, q, f, light);
  }
};

// Base's shading times up to kMaxProjectiveTextures maps.
template <class Base>
struct SinglePassShader {
  using Vertex = typename Base::Vertex;
  using Varyings = typename Base::Varyings;
  static constexpr bool kDiscards = raster::shader_discards<Base>();  // a masked surface's alpha test
  Base base;
  std::array<const shading::tech::ProjectiveReader*, kMaxProjectiveTextures> readers{};
  std::array<size_t, kMaxProjectiveTextures> light_of{};  // each map's light, for the record
  int count = 0;
  SurfaceRecord* record = nullptr;  // optional: Base records the surface, the maps' factors multiply in

  glm::vec4 vertex(const Vertex& v, Varyings& out) const { return base.vertex(v, out); }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    base.fragment(q, out);
    const shading::Quad<glm::vec3> p = world_positions(q);
    for (int i = 0; i < count; ++i) {
      const shading::Quad<float> f = shading::tech::projective_factors(*readers[size_t(i)], p);
      if (record) record_factors(*record, q, f, light_of[size_t(i)]);
      for (size_t l = 0; l < 4; ++l) {
        glm::vec4& c = out.color[l];
        c = glm::vec4(f[l] * c.r, f[l] * c.g, f[l] * c.b, 1.0f * c.a);
      }
    }
  }
};

// Draws scene instance `instance` (a receiver or not) with `shader` and the projective maps overlapping it,
// counting its draw calls in pf.stats.receiver_draws.
template <class Shader>
raster::DrawStats draw_receiver(raster::Renderer& renderer, raster::RenderTargets targets, const raster::DrawState& s,
                                const Shader& shader, std::span<const typename Shader::Vertex> vertices,
                                std::span<const uint32_t> indices, ProjectiveFrame& pf, size_t instance,
                                SurfaceRecord* record = nullptr) {
  if (instance >= pf.stats.receiver_draws.size()) pf.stats.receiver_draws.resize(instance + 1, 0);
  uint32_t& draws = pf.stats.receiver_draws[instance];
  const std::span<const Overlap> list =
      instance < pf.overlaps.size() ? std::span<const Overlap>(pf.overlaps[instance]) : std::span<const Overlap>();
  ++draws;
  if (list.empty()) return renderer.draw(targets, s, shader, vertices, indices);

  raster::DrawStats stats;
  size_t done = 0;
  if (pf.mode == shading::tech::ProjectiveMode::single_pass) {
    SinglePassShader<Shader> sp{shader};
    sp.count = int(std::min<size_t>(list.size(), size_t(std::clamp(pf.max_textures, 1, kMaxProjectiveTextures))));
    sp.record = record;
    for (int i = 0; i < sp.count; ++i) {
      const AppliedCaster& c = pf.casters[list[size_t(i)].caster];
      sp.readers[size_t(i)] = &c.reader;
      sp.light_of[size_t(i)] = c.light;
    }
    stats += renderer.draw(targets, s, sp, vertices, indices);
    done = size_t(sp.count);
  } else {
    stats += renderer.draw(targets, s, shader, vertices, indices);
  }
  raster::DrawState m = s;
  m.depth_func = raster::DepthFunc::equal;
  m.depth_write = false;
  m.blend = raster::BlendMode::multiply;
  for (size_t k = done; k < list.size(); ++k) {
    // Scissored to where this caster's shadow can fall on the receiver (outside it the factor is exactly 1).
    raster::Rect r = list[k].scissor;
    if (s.scissor) {
      const int x0 = std::max(r.x, s.scissor->x), y0 = std::max(r.y, s.scissor->y);
      const int x1 = std::min(r.x + r.width, s.scissor->x + s.scissor->width);
      const int y1 = std::min(r.y + r.height, s.scissor->y + s.scissor->height);
      r = raster::Rect{x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
    }
    m.scissor = r;
    const AppliedCaster& c = pf.casters[list[k].caster];
    stats += renderer.draw(targets, m, ApplyShader<Shader>{shader, &c.reader, record, c.light}, vertices, indices);
    ++draws;
    ++pf.stats.shadow_passes;
  }
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace frame
