// The per-pixel aliasing measure and its heat map (see aliasing.h).
#include "scenes/frame/aliasing.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include "raster/parallel_clear.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

namespace {

// Pixels per texel along the worse axis: 1 / the smaller singular value of J = [dT/dx dT/dy].
float pixels_per_texel(glm::vec2 dx, glm::vec2 dy) {
  const float a = glm::dot(dx, dx), b = glm::dot(dx, dy), c = glm::dot(dy, dy);
  // Eigenvalues of JᵀJ = [[a, b], [b, c]]; the smaller is σ_min².
  const float mean = 0.5f * (a + c), root = std::sqrt(std::max(0.0f, 0.25f * (a - c) * (a - c) + b * b));
  const float s2 = std::max(mean - root, 0.0f);
  return s2 > 1.0f / (kRatioCap * kRatioCap) ? std::min(1.0f / std::sqrt(s2), kRatioCap) : kRatioCap;
}

struct AliasingShader {
  using Vertex = CameraVertex;
  struct Varyings {
    glm::vec3 world;
    glm::vec3 normal;
  };
  glm::mat4 model{1.0f}, view_proj{1.0f};
  glm::mat3 normal_matrix{1.0f};
  const LightRecord* light = nullptr;

  glm::vec4 vertex(const Vertex& v, Varyings& out) const {
    const glm::vec4 w = model * glm::vec4(v.position, 1.0f);
    out.world = glm::vec3(w);
    out.normal = normal_matrix * v.normal;
    return view_proj * w;
  }

  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (int lane = 0; lane < 4; ++lane) {
      if (((q.live >> lane) & 1u) == 0) continue;
      const Varyings& v = q.in[size_t(lane)];
      glm::vec3 n = glm::normalize(v.normal);
      if (!q.front_facing) n = -n;
      float ratio = kUnmeasured;
      if (glm::dot(n, shading::sample_light(light->light, v.world).to_light) > 0.0f) {
        // The lanes beside this one along x and y (lanes 0 1 / 2 3); the sign of a difference does not change
        // the singular values.
        const glm::vec3 others[2] = {q.in[size_t(lane ^ 1)].world, q.in[size_t(lane ^ 2)].world};
        glm::vec2 t[3];
        if (light->shadow->texel_coords(v.world, others, t)) ratio = pixels_per_texel(t[1] - t[0], t[2] - t[0]);
      }
      out.color[size_t(lane)] = glm::vec4(ratio, 0.0f, 0.0f, 1.0f);
    }
  }
};

void summarise(AliasingImage& img) {
  std::vector<float> v;
  double sum = 0.0;
  for (float r : img.ratio)
    if (r >= 0.0f) v.push_back(r), sum += r;
  img.measured = v.size();
  if (v.empty()) return;
  const size_t k = std::min(v.size() - 1, size_t(std::ceil(0.95 * double(v.size()))) - 1);
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  img.p95 = v[k];
  img.max = *std::max_element(v.begin(), v.end());
  img.mean = float(sum / double(v.size()));
}

}  // namespace

std::vector<AliasingImage> measure_aliasing(const scenes::Scene& scene, const glm::mat4& view_proj,
                                            std::span<const LightRecord> records,
                                            std::span<const std::vector<CameraVertex>> mesh_vertices,
                                            raster::DepthTarget& camera_depth, raster::Renderer& renderer) {
  const int w = camera_depth.width(), h = camera_depth.height();
  std::vector<AliasingImage> out;
  for (const LightRecord& l : records) {
    AliasingImage img;
    img.width = w, img.height = h;
    img.ratio.assign(size_t(w) * size_t(h), kUnmeasured);
    if (l.shadow) {
      raster::ColorTarget target(w, h, raster::ColorFormat::rgba32f);
      raster::clear_on_workers(target, glm::vec4(kUnmeasured, 0.0f, 0.0f, 0.0f), renderer.pool());
      for (const scenes::Instance& inst : scene.instances) {
        if (!inst.receives_shadows) continue;
        const scenes::Mesh& mesh = scene.meshes.at(inst.mesh);
        const std::vector<CameraVertex>& vs = mesh_vertices[inst.mesh];
        AliasingShader shader;
        shader.model = inst.transform;
        shader.normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
        shader.view_proj = view_proj;
        shader.light = &l;
        raster::DrawState s;
        s.depth_func = raster::DepthFunc::equal;
        s.depth_write = false;
        s.cull = scene.materials.at(inst.material).double_sided ? raster::CullMode::none : raster::CullMode::back;
        renderer.draw(raster::RenderTargets{&camera_depth, &target}, s, shader, std::span<const CameraVertex>(vs),
                      std::span<const uint32_t>(mesh.indices));
      }
      for (int y = 0; y < h; ++y) {
        const float* row = target.row32f(y);
        for (int x = 0; x < w; ++x) img.ratio[size_t(y) * size_t(w) + size_t(x)] = row[4 * x];
      }
      summarise(img);
    }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (!(camera_depth.value(x, y) < 1.0f)) img.ratio[size_t(y) * size_t(w) + size_t(x)] = kEmpty;
    out.push_back(std::move(img));
  }
  return out;
}

raster::ColorTarget aliasing_heat_map(const AliasingImage& img) {
  raster::ColorTarget out(img.width, img.height, raster::ColorFormat::rgba32f);
  // Stops of log2(ratio): −2 blue, 0 green, 1 yellow, 3 red.
  const struct { float at; glm::vec3 c; } stops[] = {
      {-2.0f, {0.05f, 0.1f, 0.8f}}, {0.0f, {0.05f, 0.6f, 0.1f}}, {1.0f, {0.9f, 0.8f, 0.05f}}, {3.0f, {0.8f, 0.02f, 0.02f}}};
  for (int y = 0; y < img.height; ++y) {
    float* row = out.row32f(y);
    for (int x = 0; x < img.width; ++x) {
      const float r = img.ratio[size_t(y) * size_t(img.width) + size_t(x)];
      glm::vec3 c(0.0f);
      if (r >= 0.0f) {
        const float l = std::clamp(std::log2(std::max(r, 1e-6f)), -2.0f, 3.0f);
        size_t k = 0;
        while (k + 2 < std::size(stops) && l > stops[k + 1].at) ++k;
        const float t = std::clamp((l - stops[k].at) / (stops[k + 1].at - stops[k].at), 0.0f, 1.0f);
        c = glm::mix(stops[k].c, stops[k + 1].c, t);
      } else if (r == kUnmeasured) {
        c = glm::vec3(0.08f);
      }
      row[4 * x + 0] = c.r, row[4 * x + 1] = c.g, row[4 * x + 2] = c.b, row[4 * x + 3] = 1.0f;
    }
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace frame
