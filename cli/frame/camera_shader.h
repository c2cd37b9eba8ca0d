// The camera pass's shader: world position and normal as perspective-correct varyings, Blinn-Phong per light
// (shading/lighting.h) with the ambient term untouched and diffuse + specular scaled by the light's shadow
// visibility. A template over the shadow filter, so the filter is chosen once per draw (dispatch_filter).
#pragma once
#include <span>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "raster/shader.h"
#include "shading/lighting.h"
#include "shading/techniques/classic.h"

namespace frame {

struct CameraVertex {
  glm::vec3 position;  // model space
  glm::vec3 normal;
};

// One light as the camera pass reads it; `reader` is used only when `shadowed`.
struct LightRecord {
  shading::Light light;
  bool shadowed = false;
  shading::tech::ClassicReader reader;
};

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

template <class Filter, bool kPcfTaps>
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

  glm::vec3 shade(glm::vec3 p, glm::vec3 n, glm::vec2 frag) const {
    const glm::vec3 v = glm::normalize(u.eye - p);
    glm::vec3 c(0.0f);
    for (const LightRecord& l : lights) {
      const shading::LightSample ls = shading::sample_light(l.light, p);
      const shading::DirectLight d = shading::direct_light(u.material, ls, n, v);
      c += u.material.albedo * l.light.color * u.material.ambient;
      if (d.diffuse == glm::vec3(0.0f) && d.specular == glm::vec3(0.0f)) continue;
      const float vis = l.shadowed && u.receives_shadows
                            ? shading::tech::classic_visibility<Filter, kPcfTaps>(l.reader, p, n, frag)
                            : 1.0f;
      c += vis * (d.diffuse + d.specular * u.specular_color);
    }
    return c;
  }

  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (int lane = 0; lane < 4; ++lane) {
      if (((q.live >> lane) & 1u) == 0) continue;  // helper lane: never written
      const Varyings& in = q.in[size_t(lane)];
      glm::vec3 n = glm::normalize(in.normal);
      if (!q.front_facing) n = -n;  // double-sided surfaces light their back side
      const glm::vec4& fc = q.frag_coord[size_t(lane)];
      out.color[size_t(lane)] = glm::vec4(shade(in.world, n, glm::vec2(fc.x, fc.y)), 1.0f);
    }
  }
};

}  // namespace frame
