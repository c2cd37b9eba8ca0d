// Measurements of the bias options on the built-in `tutorial` (320 × 180, 1024² d16, hard filter): shadow acne
// (camera pixels facing the light, unoccluded by a ray cast towards it and at least 2 pixels from any truly
// shadowed pixel, that the map still puts in shadow) and peter-panning (the lit gap on the floor between the
// cylinder's base and where its shadow starts). Prints a table; asserts only what the tutorial promises.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "scenes/frame/camera_shader.h"
#include "shading/techniques/technique.h"
#include "scenes/frame/frame_lights.h"
#include "scenes/builtin_scenes.h"
#include "scenes/camera_math.h"
#include "scenes/scene_queries.h"
#include "tests/support.h"

namespace tech = shading::tech;

namespace {

constexpr int W = 320, H = 180;

// Writes the world position (kNormal = false) or the normal into an RGBA32F target.
template <bool kNormal>
struct GBufferShader {
  using Vertex = frame::CameraVertex;
  struct Varyings {
    glm::vec3 world, normal;
  };
  glm::mat4 model, normal_matrix, view_proj;
  glm::vec4 vertex(const Vertex& v, Varyings& o) const {
    const glm::vec4 w = model * glm::vec4(v.position, 1.0f);
    o.world = glm::vec3(w);
    o.normal = glm::vec3(normal_matrix * glm::vec4(v.normal, 0.0f));
    return view_proj * w;
  }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (int l = 0; l < 4; ++l)
      out.color[size_t(l)] = kNormal ? glm::vec4(glm::normalize(q.in[size_t(l)].normal), 1.0f)
                                     : glm::vec4(q.in[size_t(l)].world, 1.0f);
  }
};

template <bool kNormal>
raster::ColorTarget gbuffer(raster::Renderer& r, const scenes::Scene& scene, const glm::mat4& vp) {
  raster::ColorTarget c(W, H, raster::ColorFormat::rgba32f);
  raster::DepthTarget d(W, H, raster::DepthFormat::d24);
  c.clear(glm::vec4(0.0f));
  d.clear(1.0f);
  for (const scenes::Instance& inst : scene.instances) {
    const scenes::Mesh& m = scene.meshes[inst.mesh];
    std::vector<frame::CameraVertex> v(m.positions.size());
    for (size_t i = 0; i < v.size(); ++i) v[i] = {m.positions[i], m.normals[i]};
    GBufferShader<kNormal> s{inst.transform, glm::transpose(glm::inverse(inst.transform)), vp};
    raster::DrawState st;
    st.cull = raster::CullMode::back;
    r.draw(raster::RenderTargets{&d, &c}, st, s, std::span<const frame::CameraVertex>(v), m.indices);
  }
  return c;
}

// Möller–Trumbore against every triangle: does the ray from o along dir hit anything at t > 0?
bool occluded(const scenes::TriangleSoup& soup, glm::vec3 o, glm::vec3 dir) {
  for (size_t k = 0; k < soup.indices.size(); k += 3) {
    const glm::vec3 a = soup.positions[soup.indices[k]], b = soup.positions[soup.indices[k + 1]],
                    c = soup.positions[soup.indices[k + 2]];
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) continue;
    const float inv = 1.0f / det;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f) continue;
    if (glm::dot(e2, q) * inv > 1e-4f) return true;
  }
  return false;
}

// The tutorial light's classic map built through the registry, as render_frame builds it.
using Built = std::unique_ptr<tech::LightShadow>;

Built build(raster::Renderer& r, const scenes::Scene& scene, const glm::mat4& vp, const frame::FrameConfig& o) {
  const frame::ResolvedLight rl = frame::resolve_light(scene.lights[0], 0, o);
  tech::PlanInputs in;
  in.casters = tech::Box{scenes::scene_bounds(scene, scenes::InstanceFilter::casters).min,
                         scenes::scene_bounds(scene, scenes::InstanceFilter::casters).max};
  const scenes::Aabb rb = scenes::scene_bounds(scene, scenes::InstanceFilter::receivers);
  in.receivers = tech::camera_receiver_box(vp, tech::Box{rb.min, rb.max});
  const scenes::TriangleSoup soup = scenes::flatten(scene, scenes::InstanceFilter::casters);
  Built b = tech::find_impl(rl.config.technique)->plan(rl.desc, rl.config, in);
  b->build(r, tech::CasterGeometry{soup.positions, soup.indices});
  return b;
}

// One point's visibility (the frame reads quads; one point is a batch of one).
float visibility(const Built& b, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  const tech::ShadowQuery q{p, n, frag};
  float v = 1.0f;
  b->visibility(std::span(&q, 1), std::span(&v, 1));
  return v;
}

TEST(BiasMeasure, TutorialAcneAndPeterPanning) {
  const scenes::Scene scene = scenes::builtin_scene("tutorial");
  const scenes::Camera& cam = scene.cameras[0];
  const glm::mat4 vp = scenes::projection_matrix(cam, float(W) / H) * scenes::view_matrix(cam);
  raster::Renderer r(testsupport::test_threads());
  const raster::ColorTarget pos = gbuffer<false>(r, scene, vp), nrm = gbuffer<true>(r, scene, vp);
  const scenes::TriangleSoup soup = scenes::flatten(scene, scenes::InstanceFilter::casters);
  const glm::vec3 to_light = -glm::normalize(scene.lights[0].direction);

  // Ground truth per pixel: 0 background or facing away, 1 lit, 2 shadowed.
  std::vector<uint8_t> truth(size_t(W) * H, 0);
  r.pool().parallel_for(H, [&](size_t y) {
    for (int x = 0; x < W; ++x) {
      const glm::vec4 p = pos.read(x, int(y)), n = nrm.read(x, int(y));
      if (p.w == 0.0f || glm::dot(glm::vec3(n), to_light) < 0.05f) continue;
      truth[y * W + size_t(x)] = occluded(soup, glm::vec3(p) + glm::vec3(n) * 1e-3f, to_light) ? 2 : 1;
    }
  });
  auto robustly_lit = [&](int x, int y) {
    if (truth[size_t(y) * W + size_t(x)] != 1) return false;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx >= 0 && yy >= 0 && xx < W && yy < H && truth[size_t(yy) * W + size_t(xx)] == 2) return false;
      }
    return true;
  };

  // The cylinder (radius 0.8 at (−2, ·, −1.5)) stands on the floor; its shadow leaves the base along the
  // horizontal part of the light's direction. Floor height from a ray cast down beside it.
  const glm::vec3 d = glm::normalize(scene.lights[0].direction);
  const glm::vec2 h = glm::normalize(glm::vec2(d.x, d.z));
  float floor_y = 0.0f;
  for (float y = 1.0f; y > -1.0f; y -= 0.001f)
    if (occluded(soup, {0.0f, y, 3.0f}, {0, 1, 0}) == false && occluded(soup, {0.0f, y - 0.001f, 3.0f}, {0, 1, 0})) {
      floor_y = y - 0.0005f;
      break;
    }
  const glm::vec3 contact(-2.0f + 0.8f * h.x, floor_y, -1.5f + 0.8f * h.y);

  std::printf("tutorial, 320x180, 1024^2 d16, hard filter (floor at y = %.4f)\n", floor_y);
  std::printf("%-14s %10s %12s %14s\n", "bias", "acne px", "of lit px", "gap (mm)");
  const char* kBiases[] = {"none", "constant", "slope", "offset", "normal"};
  int acne_by_bias[5] = {};
  for (bool cull_front : {false, true})
    for (int bi = 0; bi < 5; ++bi) {
      frame::FrameConfig o;
      o.width = W;
      o.height = H;
      o.map_size = 1024;
      o.filter = *shading::tech::parse_filter("hard");
      o.bias = *shading::tech::parse_bias_mode(kBiases[bi]);
      o.cull_front = cull_front;
      const Built b = build(r, scene, vp, o);
      int acne = 0, lit = 0;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          if (!robustly_lit(x, y)) continue;
          ++lit;
          const glm::vec3 p(pos.read(x, y)), n(nrm.read(x, y));
          if (visibility(b, p, n, {x + 0.5f, y + 0.5f}) < 0.5f) ++acne;
        }
      float gap = -1.0f;
      for (int mm = 1; mm <= 1000; ++mm) {
        const glm::vec3 p = contact + glm::vec3(h.x, 0.0f, h.y) * (float(mm) * 0.001f);
        if (visibility(b, p, {0, 1, 0}, {0, 0}) < 0.5f) {
          gap = float(mm - 1);
          break;
        }
      }
      if (std::getenv("SHADOWLAB_BIAS_DEBUG")) {
        const glm::mat4 ndc = b->maps().at(0).world_to_ndc * glm::inverse(b->maps().at(0).world_to_camera);
        std::printf("  depth range %.3f m; vis at 1,10,50,100,200 mm:", 2.0f / ndc[2][2]);
        for (int mm : {1, 10, 50, 100, 200})
          std::printf(" %.2f", visibility(
                                   b, contact + glm::vec3(h.x, 0.0f, h.y) * (float(mm) * 0.001f), {0, 1, 0}, {0, 0}));
        std::printf("\n");
      }
      std::printf("%-8s%-6s %10d %12d %14.0f\n", kBiases[bi], cull_front ? "+back" : "", acne, lit, gap);
      if (!cull_front) acne_by_bias[bi] = acne;
    }
  EXPECT_GT(acne_by_bias[0], 100);  // no bias: acne everywhere the light grazes
  EXPECT_LT(acne_by_bias[2], acne_by_bias[0] / 10);
}

}  // namespace
