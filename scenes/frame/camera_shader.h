// The camera pass's shader: world position and normal as perspective-correct varyings, Blinn-Phong per light
// (shading/lighting.h) with the ambient term untouched and diffuse + specular scaled by the light's shadow
// visibility. It writes luminance (cd/m², float) with alpha 1 where a surface is drawn; the frame's exposure and
// tone map turn it into a picture (develop.h). Each light is read through its technique's LightShadow with its own filter, once per quad
// (light_visibility) or, on the pipeline's wide path (fragment_pair), once per quad pair eight lanes wide.
// Textured materials (BasicCameraShader<true, ...>) take their albedo from factor × texture per pixel
// (shading/surface_texture.h) on the quad path, and masked ones discard where alpha is below the cutoff.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "raster/shader.h"
#include "raster/simd/vec.h"
#include "scenes/frame/surface_record.h"
#include "shading/lighting.h"
#include "shading/surface_texture.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

struct CameraVertex {
  glm::vec3 position;  // model space
  glm::vec3 normal;
};

// The vertex of a textured draw: texture coordinates too (GL's (s, t), scenes::Mesh::texcoords).
struct TexturedCameraVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 st;
};

// One light as the camera pass reads it: its shadow (the technique's LightShadow, owned by the frame; null
// where the light casts none) is asked once per quad or quad pair.
struct LightRecord {
  shading::Light light;
  const shading::tech::LightShadow* shadow = nullptr;
};

// Visibility of a batch of points (a quad's) from one light; 1 where the light casts no shadow.
inline void light_visibility(const LightRecord& l, std::span<const shading::tech::ShadowQuery> q, std::span<float> vis) {
  if (l.shadow) return l.shadow->visibility(q, vis);
  for (float& v : vis) v = 1.0f;
}

// The same for up to eight points (a quad pair's), bit-identical per point (LightShadow::visibility_x8).
inline void light_visibility_x8(const LightRecord& l, std::span<const shading::tech::ShadowQuery> q,
                                std::span<float> vis) {
  if (l.shadow) return l.shadow->visibility_x8(q, vis);
  for (float& v : vis) v = 1.0f;
}

// Per-draw (per instance) uniforms besides the filter.
struct SurfaceUniforms {
  glm::mat4 model{1.0f};
  glm::mat3 normal_matrix{1.0f};
  glm::mat4 view_proj{1.0f};
  glm::vec3 eye{0.0f};
  shading::Material material;
  glm::vec3 specular_color{1.0f};
  bool receives_shadows = true;
};

// kTextured: the albedo is SurfaceTexture::color per pixel (the quad path only: the texture's LOD comes from
// the quad); kMasked: lanes whose alpha is below the cutoff are discarded (early depth testing is then off for
// the draw). The plain shader (CameraShader) keeps the material's albedo and the wide path.
template <bool kTextured, bool kMasked = false>
struct BasicCameraShader {
  static_assert(kTextured || !kMasked, "the alpha test reads the texture");
  using Vertex = std::conditional_t<kTextured, TexturedCameraVertex, CameraVertex>;
  struct Varyings {
    glm::vec3 world;
    glm::vec3 normal;
    [[no_unique_address]] std::conditional_t<kTextured, glm::vec2, raster::NoVaryings> st;
  };
  static constexpr bool kDiscards = kMasked;

  SurfaceUniforms u;
  std::span<const LightRecord> lights;  // owned by the frame, alive for the draw
  SurfaceRecord* record = nullptr;       // optional per-pixel record (surface_record.h), owned by the frame
  const shading::SurfaceTexture* surface = nullptr;  // kTextured: the material's base colour, owned by the frame

  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    const glm::vec4 w = u.model * glm::vec4(v.position, 1.0f);
    out.world = glm::vec3(w);
    out.normal = u.normal_matrix * v.normal;
    if constexpr (kTextured) out.st = v.st;
    return u.view_proj * w;
  }

  // Lights are the outer loop so that each light's reader makes its choices once per quad; helper lanes are
  // neither shaded nor looked up.
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    Points<4> pts;
    // The quad's position differences (helper lanes are interpolated too): the shadow lookups' derivatives and
    // the recorded plane's normal.
    const glm::vec3 dx = q.in[1].world - q.in[0].world, dy = q.in[2].world - q.in[0].world;
    shading::Quad<glm::vec3> albedo{u.material.albedo, u.material.albedo, u.material.albedo, u.material.albedo};
    unsigned live = q.live;
    if constexpr (kTextured) {
      const shading::Quad<glm::vec4> c = surface->color({q.in[0].st, q.in[1].st, q.in[2].st, q.in[3].st});
      for (size_t l = 0; l < 4; ++l) albedo[l] = glm::vec3(c[l]);
      if constexpr (kMasked) {
        out.discard = surface->discarded(c);
        live &= ~unsigned(out.discard);
      }
    }
    for (int lane = 0; lane < 4; ++lane) {
      if (((live >> lane) & 1u) == 0) continue;  // helper lane (or discarded): never written
      const glm::vec4& fc = q.frag_coord[size_t(lane)];
      pts.add(*this, q.in[size_t(lane)], q.front_facing, glm::vec2(fc.x, fc.y), lane, albedo[size_t(lane)], dx, dy);
      if (record) pts.surface[pts.n - 1] = {dx, dy, fc.z};
    }
    shade(pts, [](const LightRecord& l, auto q, auto vis) { light_visibility(l, q, vis); });
    for (size_t i = 0; i < pts.n; ++i) out.color[size_t(pts.lane_of[i])] = glm::vec4(pts.color[i], 1.0f);
  }

  // The same on a quad pair, pixel by pixel the same operations, with each light's visibility asked for the
  // pair's covered pixels at once so the filters run eight lanes wide (light_visibility_x8).
  void fragment_pair(const raster::QuadPairIn<Varyings>& q, raster::QuadPairOut& out) const
    requires(!kTextured)
  {
    static_assert(raster::kVaryingFloats<Varyings> == 6);
    alignas(32) float in[6][8], fx[8], fy[8];
    for (size_t k = 0; k < 6; ++k) q.in[k].store(in[k]);
    q.frag_x.store(fx), q.frag_y.store(fy);
    Points<8> pts;
    alignas(32) float fz[8];
    if (record) q.frag_z.store(fz);
    auto world = [&](int lane) { return glm::vec3(in[0][lane], in[1][lane], in[2][lane]); };
    for (int lane = 0; lane < 8; ++lane) {
      if (((q.live >> lane) & 1u) == 0) continue;  // helper lane: never written
      const Varyings v{{in[0][lane], in[1][lane], in[2][lane]}, {in[3][lane], in[4][lane], in[5][lane]}, {}};
      // The lane's own quad (lanes b, b + 1, b + 4, b + 5): the same differences as fragment().
      const int b = lane & 2;
      const glm::vec3 dx = world(b + 1) - world(b), dy = world(b + 4) - world(b);
      pts.add(*this, v, q.front_facing, glm::vec2(fx[lane], fy[lane]), lane, u.material.albedo, dx, dy);
      if (record) pts.surface[pts.n - 1] = {dx, dy, fz[lane]};
    }
    shade(pts, [](const LightRecord& l, auto q, auto vis) { light_visibility_x8(l, q, vis); });
    alignas(32) float ch[4][8] = {};
    for (size_t i = 0; i < pts.n; ++i) {
      const int lane = pts.lane_of[i];
      ch[0][lane] = pts.color[i].r, ch[1][lane] = pts.color[i].g, ch[2][lane] = pts.color[i].b, ch[3][lane] = 1.0f;
    }
    for (size_t c = 0; c < 4; ++c) out.color[c] = raster::simd::VecF32::load(ch[c]);
  }

 private:
  // The covered pixels of a quad or pair, packed: what a light's visibility is asked for, and their colours.
  template <size_t N>
  struct Points {
    std::array<shading::tech::ShadowQuery, N> q;
    std::array<glm::vec3, N> view, color, albedo;
    std::array<int, N> lane_of;
    struct Surface {
      glm::vec3 dx, dy;  // world position one pixel right and one up, minus the quad's first
      float depth;       // window depth
    };
    std::array<Surface, N> surface;  // filled only when recording
    size_t n = 0;
    void add(const BasicCameraShader& s, const Varyings& in, bool front_facing, glm::vec2 frag, int lane,
             glm::vec3 surface_albedo, glm::vec3 dpdx, glm::vec3 dpdy) {
      glm::vec3 nrm = glm::normalize(in.normal);
      if (!front_facing) nrm = -nrm;  // double-sided surfaces light their back side
      q[n] = {in.world, nrm, frag, dpdx, dpdy};
      view[n] = glm::normalize(s.u.eye - in.world);
      color[n] = glm::vec3(0.0f);
      albedo[n] = surface_albedo;
      lane_of[n++] = lane;
    }
  };

  // Blinn-Phong over every light, the points' visibility from `visibility` (a batch reader, once per light).
  template <size_t N, class Visibility>
  void shade(Points<N>& pts, Visibility&& visibility) const {
    for (const LightRecord& l : lights) {
      std::array<shading::DirectLight, N> d;
      std::array<shading::tech::ShadowQuery, N> lit_pts;
      std::array<size_t, N> lit_of;
      size_t m = 0;
      for (size_t i = 0; i < pts.n; ++i) {
        shading::Material surface_material = u.material;
        surface_material.albedo = pts.albedo[i];  // the material's, or factor × texture
        const shading::LightSample ls = shading::sample_light(l.light, pts.q[i].p);
        d[i] = shading::direct_light(surface_material, ls, pts.q[i].n, pts.view[i]);
        pts.color[i] += shading::ambient_light(surface_material, ls);
        if (d[i].diffuse == glm::vec3(0.0f) && d[i].specular == glm::vec3(0.0f)) continue;
        lit_pts[m] = pts.q[i];
        lit_of[m++] = i;
      }
      std::array<float, N> vis;
      vis.fill(1.0f);
      if (u.receives_shadows && m > 0) visibility(l, std::span(lit_pts.data(), m), std::span(vis.data(), m));
      for (size_t k = 0; k < m; ++k) {
        const size_t i = lit_of[k];
        pts.color[i] += vis[k] * (d[i].diffuse + d[i].specular * u.specular_color);
      }
      if (record) record_light(pts, size_t(&l - lights.data()), std::span(lit_of.data(), m), std::span(vis.data(), m));
    }
    if (record) record_surface(pts);
  }

  // The pixel a point lies on (its centre is at integer + 0.5).
  static size_t pixel_of(const SurfaceRecord& r, glm::vec2 frag) { return r.index(int(frag.x), int(frag.y)); }

  template <size_t N>
  void record_light(const Points<N>& pts, size_t light, std::span<const size_t> lit_of, std::span<const float> vis) const {
    SurfaceRecord& r = *record;
    for (size_t i = 0; i < pts.n; ++i) {
      const size_t p = pixel_of(r, pts.q[i].frag) * r.lights + light;
      r.lit_facing[p] = 0;
      r.visibility[p] = 1.0f;
    }
    if (!u.receives_shadows) return;  // the light reaches these points but its technique is not asked
    for (size_t k = 0; k < lit_of.size(); ++k) {
      const size_t p = pixel_of(r, pts.q[lit_of[k]].frag) * r.lights + light;
      r.lit_facing[p] = 1;
      r.visibility[p] = vis[k];
    }
  }

  template <size_t N>
  void record_surface(const Points<N>& pts) const {
    SurfaceRecord& r = *record;
    for (size_t i = 0; i < pts.n; ++i) {
      const size_t p = pixel_of(r, pts.q[i].frag);
      const auto& s = pts.surface[i];
      glm::vec3 n = glm::cross(s.dx, s.dy);  // screen x cross screen y: towards the viewer
      const float len = glm::length(n);
      n = len > 0.0f ? n / len : pts.q[i].n;  // a degenerate quad: the shading normal
      r.covered[p] = 1;
      r.position[p] = pts.q[i].p;
      r.normal[p] = n;
      r.depth[p] = s.depth;
    }
  }
};

using CameraShader = BasicCameraShader<false>;

SHADOWLAB_ISA_END
}  // namespace frame
