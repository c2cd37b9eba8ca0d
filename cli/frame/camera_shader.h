// The camera pass's shader: world position and normal as perspective-correct varyings, Blinn-Phong per light
// (shading/lighting.h) with the ambient term untouched and diffuse + specular scaled by the light's shadow
// visibility. Each light is read with its own technique and filter, chosen once per quad (light_visibility).
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "raster/shader.h"
#include "shading/lighting.h"
#include "shading/techniques/classic.h"
#include "shading/techniques/omni_read.h"

namespace frame {

struct CameraVertex {
  glm::vec3 position;  // model space
  glm::vec3 normal;
};

// How a light's shadow is read in the camera pass. Each kind has a reader snapshotted once per frame and a
// batch visibility function (per quad) that makes its run-time choices (filter, lookup) once per batch.
enum class ShadowRead : uint8_t { none, classic, omni };

// One light as the camera pass reads it; the reader matching `read` is used.
struct LightRecord {
  shading::Light light;
  ShadowRead read = ShadowRead::none;
  shading::tech::ClassicReader classic;
  shading::tech::OmniReader omni;  // cube, paraboloid or pyramid
};

// Visibility of up to four points of a quad from one light; 1 where the light casts no shadow.
inline void light_visibility(const LightRecord& l, std::span<const shading::tech::ShadowQuery> q, std::span<float> vis) {
  switch (l.read) {
    case ShadowRead::classic: shading::tech::classic_visibility(l.classic, q, vis); return;
    case ShadowRead::omni: shading::tech::omni_visibility(l.omni, q, vis); return;
    case ShadowRead::none: break;
  }
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

struct CameraShader {
  using Vertex = CameraVertex;
  struct Varyings {
    glm::vec3 world;
    glm::vec3 normal;
  };

  SurfaceUniforms u;
  std::span<const LightRecord> lights;  // owned by the frame, alive for the draw

  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    const glm::vec4 w = u.model * glm::vec4(v.position, 1.0f);
    out.world = glm::vec3(w);
    out.normal = u.normal_matrix * v.normal;
    return u.view_proj * w;
  }

  // Lights are the outer loop so that each light's reader makes its choices once per quad; helper lanes are
  // neither shaded nor looked up.
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    std::array<shading::tech::ShadowQuery, 4> pts;
    std::array<glm::vec3, 4> view, color;
    std::array<int, 4> lane_of;
    size_t n = 0;
    for (int lane = 0; lane < 4; ++lane) {
      if (((q.live >> lane) & 1u) == 0) continue;  // helper lane: never written
      const Varyings& in = q.in[size_t(lane)];
      glm::vec3 nrm = glm::normalize(in.normal);
      if (!q.front_facing) nrm = -nrm;  // double-sided surfaces light their back side
      const glm::vec4& fc = q.frag_coord[size_t(lane)];
      pts[n] = {in.world, nrm, glm::vec2(fc.x, fc.y)};
      view[n] = glm::normalize(u.eye - in.world);
      color[n] = glm::vec3(0.0f);
      lane_of[n++] = lane;
    }
    for (const LightRecord& l : lights) {
      std::array<shading::DirectLight, 4> d;
      std::array<shading::tech::ShadowQuery, 4> lit_pts;
      std::array<size_t, 4> lit_of;
      size_t m = 0;
      for (size_t i = 0; i < n; ++i) {
        d[i] = shading::direct_light(u.material, shading::sample_light(l.light, pts[i].p), pts[i].n, view[i]);
        color[i] += u.material.albedo * l.light.color * u.material.ambient;
        if (d[i].diffuse == glm::vec3(0.0f) && d[i].specular == glm::vec3(0.0f)) continue;
        lit_pts[m] = pts[i];
        lit_of[m++] = i;
      }
      std::array<float, 4> vis{1.0f, 1.0f, 1.0f, 1.0f};
      if (u.receives_shadows && m > 0) light_visibility(l, std::span(lit_pts.data(), m), std::span(vis.data(), m));
      for (size_t k = 0; k < m; ++k) {
        const size_t i = lit_of[k];
        color[i] += vis[k] * (d[i].diffuse + d[i].specular * u.specular_color);
      }
    }
    for (size_t i = 0; i < n; ++i) out.color[size_t(lane_of[i])] = glm::vec4(color[i], 1.0f);
  }
};

}  // namespace frame
