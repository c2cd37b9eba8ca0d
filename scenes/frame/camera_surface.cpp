// The camera pass's per-instance set-up and the visible-surface pre-pass (see camera_surface.h).
#include "scenes/frame/camera_surface.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "raster/parallel_clear.h"
#include "raster/target.h"
#include "scenes/frame/surface_record.h"
#include "scenes/scene_queries.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

std::vector<CameraVertex> camera_vertices(const scenes::Mesh& m) {
  std::vector<CameraVertex> v(m.positions.size());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = CameraVertex{m.positions[i], i < m.normals.size() ? m.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f)};
  return v;
}

std::vector<TexturedCameraVertex> textured_vertices(const std::vector<CameraVertex>& plain, const scenes::Mesh& m) {
  std::vector<TexturedCameraVertex> v(plain.size());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = TexturedCameraVertex{plain[i].position, plain[i].normal,
                                i < m.texcoords.size() ? m.texcoords[i] : glm::vec2(0.0f)};
  return v;
}

raster::DrawState camera_instance(const scenes::Scene& scene, size_t index, SurfaceUniforms& u) {
  const scenes::Instance& inst = scene.instances[index];
  const scenes::Material& mat = scene.materials.at(inst.material);
  u.model = inst.transform;
  u.normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
  u.material = shading::Material{glm::vec3(mat.base_color), 0.1f, mat.specular_strength, mat.shininess};
  u.specular_color = mat.specular_color;
  u.receives_shadows = inst.receives_shadows;
  raster::DrawState s;
  s.cull = mat.double_sided ? raster::CullMode::none : raster::CullMode::back;
  return s;
}

shading::tech::CameraSurface camera_surface(const scenes::Scene& scene,
                                            std::span<const shading::SurfaceTexture> surfaces,
                                            const glm::mat4& view_proj, glm::vec3 eye, int width, int height,
                                            raster::Renderer& renderer) {
  SurfaceRecord record(width, height, 0);
  raster::DepthTarget depth(width, height, raster::DepthFormat::d24);
  depth.clear(1.0f);
  raster::ColorTarget color(width, height, raster::ColorFormat::rgba8);  // written, never read
  raster::clear_on_workers(color, glm::vec4(0.0f), renderer.pool());
  CameraShader shader;
  shader.record = &record;
  shader.u.view_proj = view_proj;
  shader.u.eye = eye;
  std::vector<std::vector<CameraVertex>> mesh_vertices(scene.meshes.size());
  std::vector<std::vector<TexturedCameraVertex>> mesh_textured(scene.meshes.size());  // masked draws only
  const raster::RenderTargets targets{&depth, &color};
  for (size_t index = 0; index < scene.instances.size(); ++index) {
    const scenes::Instance& inst = scene.instances[index];
    const scenes::Mesh& mesh = scene.meshes.at(inst.mesh);
    // As the camera pass: an instance whose material hides every fragment is not drawn, and a masked one
    // discards where its texture's alpha is below the cutoff (the same shader, so the same fragments).
    const scenes::Coverage coverage = scenes::coverage(scene.materials.at(inst.material));
    if (coverage == scenes::Coverage::hidden) continue;
    if (mesh_vertices[inst.mesh].empty()) mesh_vertices[inst.mesh] = camera_vertices(mesh);
    const raster::DrawState s = camera_instance(scene, index, shader.u);
    const std::span<const uint32_t> indices(mesh.indices);
    const shading::SurfaceTexture& surface = surfaces[inst.material];
    if (coverage == scenes::Coverage::masked && surface.texture) {
      if (mesh_textured[inst.mesh].empty()) mesh_textured[inst.mesh] = textured_vertices(mesh_vertices[inst.mesh], mesh);
      renderer.draw(targets, s, BasicCameraShader<true, true>{shader.u, shader.lights, shader.record, &surface},
                    std::span<const TexturedCameraVertex>(mesh_textured[inst.mesh]), indices);
    } else {
      renderer.draw(targets, s, shader, std::span<const CameraVertex>(mesh_vertices[inst.mesh]), indices);
    }
  }
  shading::tech::CameraSurface out;
  out.width = width, out.height = height;
  out.covered = std::move(record.covered);
  out.position = std::move(record.position);
  out.normal = std::move(record.normal);
  const scenes::Aabb b = scenes::scene_bounds(scene);  // as reference::default_epsilon
  out.epsilon = b.empty() ? 1e-4f : 1e-4f * glm::length(b.size());
  return out;
}

SHADOWLAB_ISA_END
}  // namespace frame
