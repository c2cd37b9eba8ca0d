// render_frame: per light, plan and build its shadow maps through the technique layer; then the camera pass,
// one draw per instance, each light read with its own technique and filter (see frame.h).
#include "cli/frame/frame.h"

#include <chrono>
#include <memory>
#include <stdexcept>

#include <glm/matrix.hpp>

#include "cli/frame/camera_shader.h"
#include "cli/frame/frame_lights.h"
#include "scenes/camera_math.h"
#include "scenes/scene_queries.h"

namespace frame {

namespace tech = shading::tech;

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

tech::Box to_box(const scenes::Aabb& a) { return tech::Box{a.min, a.max}; }

// The shadow state of one light that lives through the camera pass (readers view its targets).
struct LightMaps {
  ResolvedLight resolved;
  tech::ShadowMapSet set;
};

std::vector<CameraVertex> camera_vertices(const scenes::Mesh& m) {
  std::vector<CameraVertex> v(m.positions.size());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = CameraVertex{m.positions[i], i < m.normals.size() ? m.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f)};
  return v;
}

scenes::io::ExrMap exr_of(const tech::ShadowMapSet& set, const tech::ClassicSettings& s) {
  const tech::ShadowPass& p = set.passes[0];
  scenes::io::ExrMap m = scenes::io::exr_map_from(*set.targets[p.target]);
  m.world_to_camera = p.view;
  m.world_to_ndc = p.proj * p.view;
  m.technique = "shadowmap";
  m.encoding = "window-depth";
  if (const auto d = tech::find_technique_defaults("shadowmap")) m.encoding = std::string(d->encoding);
  (void)s;
  return m;
}

}  // namespace

Frame render_frame(const scenes::Scene& scene, const FrameOptions& options, raster::Renderer& renderer) {
  if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
    throw std::invalid_argument("--size: " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                                " is outside 1..16384");
  const float aspect = float(options.width) / float(options.height);
  const scenes::Camera camera = scene.cameras.empty()
                                    ? scenes::frame_camera(scenes::scene_bounds(scene))
                                    : scene.cameras.at(options.camera < scene.cameras.size()
                                                           ? options.camera
                                                           : throw std::invalid_argument(
                                                                 "--camera: index " + std::to_string(options.camera) +
                                                                 " is out of range"));
  const glm::mat4 view_proj = scenes::projection_matrix(camera, aspect) * scenes::view_matrix(camera);

  Frame frame{raster::ColorTarget(options.width, options.height, raster::ColorFormat::rgba8), {}, {}, {}, {}};

  // ---- Shadow maps, light by light.
  const auto t_shadow = Clock::now();
  std::vector<std::unique_ptr<LightMaps>> lights;
  scenes::TriangleSoup casters;
  tech::ClassicFit fit;
  bool have_casters = false;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    auto lm = std::make_unique<LightMaps>();
    lm->resolved = resolve_light(scene.lights[i], options);
    const ResolvedLight& r = lm->resolved;
    if (r.technique != "none" && !r.shadowed)
      frame.notes.push_back("light " + std::to_string(i) + " (" + scene.lights[i].name + "): technique " +
                            r.technique + " is not built yet; drawn unshadowed");
    if (r.shadowed) {
      if (!have_casters) {
        casters = scenes::flatten(scene, scenes::InstanceFilter::casters);
        fit.casters = to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::casters));
        fit.receivers = tech::camera_receiver_box(
            view_proj, to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::receivers)));
        have_casters = true;
      }
      tech::ClassicFit f = fit;
      if (r.fixed_box) f.fixed = tech::fixed_directional(r.classic.direction, glm::vec3(0.0f), {10.0f, 10.0f}, -10.0f, 20.0f);
      lm->set = tech::plan_classic_map(r.classic, r.settings, f);
      frame.stats.draws += tech::build_maps(renderer, lm->set, casters.positions, casters.indices,
                                            tech::classic_depth_options(r.settings));
      ++frame.stats.maps_rendered;
      frame.maps.push_back(exr_of(lm->set, r.settings));
      frame.map_names.push_back("light" + std::to_string(i) + "-" + scene.lights[i].name);
    }
    lights.push_back(std::move(lm));
  }
  frame.stats.shadow_ms = ms_since(t_shadow);

  // ---- Camera pass.
  const auto t_camera = Clock::now();
  std::vector<LightRecord> records;
  for (const auto& lm : lights) {
    LightRecord rec;
    rec.light = lm->resolved.light;
    if (lm->resolved.shadowed) {
      rec.read = ShadowRead::classic;
      rec.classic = tech::make_classic_reader(lm->set, lm->resolved.classic, lm->resolved.settings);
    }
    records.push_back(rec);
  }

  raster::DepthTarget depth(options.width, options.height, raster::DepthFormat::d24);
  depth.clear(1.0f);
  frame.color.clear(options.clear_color);
  std::vector<std::vector<CameraVertex>> mesh_vertices(scene.meshes.size());
  {
    CameraShader shader;
    shader.lights = records;
    shader.u.view_proj = view_proj;
    shader.u.eye = camera.position;
    for (const scenes::Instance& inst : scene.instances) {
      const scenes::Mesh& mesh = scene.meshes.at(inst.mesh);
      const scenes::Material& mat = scene.materials.at(inst.material);
      if (mesh_vertices[inst.mesh].empty()) mesh_vertices[inst.mesh] = camera_vertices(mesh);
      shader.u.model = inst.transform;
      shader.u.normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
      shader.u.material = shading::Material{glm::vec3(mat.base_color), 0.1f, mat.specular_strength, mat.shininess};
      shader.u.specular_color = mat.specular_color;
      shader.u.receives_shadows = inst.receives_shadows;
      raster::DrawState s;
      s.cull = mat.double_sided ? raster::CullMode::none : raster::CullMode::back;
      frame.stats.draws += renderer.draw(raster::RenderTargets{&depth, &frame.color}, s, shader,
                                         std::span<const CameraVertex>(mesh_vertices[inst.mesh]), mesh.indices);
    }
  }
  frame.stats.camera_ms = ms_since(t_camera);
  return frame;
}

}  // namespace frame
