// render_frame: per light, plan and build its shadow maps through the technique layer; then the camera pass,
// one draw per instance, each light read with its own technique and filter (see frame.h).
#include "cli/frame/frame.h"

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>

#include <glm/matrix.hpp>

#include "cli/frame/camera_shader.h"
#include "cli/frame/frame_lights.h"
#include "cli/frame/projective_shaders.h"
#include "cli/frame/frame_omni.h"
#include "raster/quad_path_only.h"
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
  std::optional<OmniMaps> omni;  // cube, paraboloid or pyramid
};

std::vector<CameraVertex> camera_vertices(const scenes::Mesh& m) {
  std::vector<CameraVertex> v(m.positions.size());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = CameraVertex{m.positions[i], i < m.normals.size() ? m.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f)};
  return v;
}

scenes::io::ExrMap exr_of(const tech::ShadowMapSet& set) {
  const tech::ShadowPass& p = set.passes[0];
  scenes::io::ExrMap m = scenes::io::exr_map_from(*set.targets[p.target]);
  m.world_to_camera = p.view;
  m.world_to_ndc = p.proj * p.view;
  m.technique = "shadowmap";
  m.encoding = "window-depth";
  if (const auto d = tech::find_technique_defaults("shadowmap")) m.encoding = std::string(d->encoding);
  return m;
}

}  // namespace

Frame render_frame(const scenes::Scene& scene, const FrameOptions& options, raster::Renderer& renderer,
                   FrameCache* cache) {
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
  std::optional<scenes::TriangleSoup> casters;  // flattened once, when a light first needs them
  auto caster_soup = [&]() -> const scenes::TriangleSoup& {
    if (!casters) casters = scenes::flatten(scene, scenes::InstanceFilter::casters);
    return *casters;
  };
  std::optional<tech::ClassicFit> fit;  // what directional boxes are fitted to, computed once
  auto add_map = [&](scenes::io::ExrMap map, size_t light) {
    ++frame.stats.maps_rendered;
    frame.maps.push_back(std::move(map));
    frame.map_names.push_back("light" + std::to_string(light) + "-" + scene.lights[light].name);
  };
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    auto lm = std::make_unique<LightMaps>();
    lm->resolved = resolve_light(scene.lights[i], options);
    const ResolvedLight& r = lm->resolved;
    if (const auto plan = resolve_omni(scene.lights[i], r, options, i)) {
      const scenes::TriangleSoup& soup = caster_soup();
      lm->omni = plan_omni(*plan);
      frame.stats.draws += build_omni(renderer, *lm->omni, soup.positions, soup.indices);
      add_map(omni_exr(*lm->omni), i);
    } else if (r.technique != "none" && r.technique != "projective" && !r.shadowed)
      frame.notes.push_back("light " + std::to_string(i) + " (" + scene.lights[i].name + "): technique " +
                            r.technique + " is not built yet; drawn unshadowed");
    if (r.shadowed) {
      const scenes::TriangleSoup& soup = caster_soup();
      if (!fit) {
        fit.emplace();
        fit->casters = to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::casters));
        fit->receivers = tech::camera_receiver_box(
            view_proj, to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::receivers)));
      }
      tech::ClassicFit f = *fit;
      if (r.fixed_box) f.fixed = tech::fixed_directional(r.classic.direction, glm::vec3(0.0f), {10.0f, 10.0f}, -10.0f, 20.0f);
      lm->set = tech::plan_classic_map(r.classic, r.settings, f);
      frame.stats.draws += tech::build_maps(renderer, lm->set, soup.positions, soup.indices,
                                            tech::classic_depth_options(r.settings));
      add_map(exr_of(lm->set), i);
    }
    lights.push_back(std::move(lm));
  }
  // Per-caster projective maps (frame_projective.h), from the cache where nothing changed.
  FrameCache local_cache;
  ProjectiveFrame projective = prepare_projective(
      scene,
      ProjectiveOverrides{options.technique, options.projective_mode, options.shadow_size, options.projective_textures,
                          options.export_maps},
      ProjectiveView{view_proj, options.width, options.height}, renderer, (cache ? *cache : local_cache).projective);
  frame.stats.maps_rendered += projective.stats.maps_rebuilt;
  for (size_t m = 0; m < projective.maps.size(); ++m) {
    frame.maps.push_back(std::move(projective.maps[m]));
    frame.map_names.push_back(projective.map_names[m]);
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
    } else if (lm->omni) {
      rec.read = ShadowRead::omni;
      rec.omni = omni_reader(*lm->omni);
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
    for (size_t index = 0; index < scene.instances.size(); ++index) {
      const scenes::Instance& inst = scene.instances[index];
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
      // Drawn once, plus the projective maps overlapping it (projective_shaders.h).
      auto draw = [&](const auto& sh) {
        return draw_receiver(renderer, raster::RenderTargets{&depth, &frame.color}, s, sh,
                             std::span<const CameraVertex>(mesh_vertices[inst.mesh]),
                             std::span<const uint32_t>(mesh.indices), projective, index);
      };
      frame.stats.draws += options.quad_fragments ? draw(raster::QuadPathOnly<CameraShader>{shader}) : draw(shader);
    }
  }
  frame.stats.camera_ms = ms_since(t_camera);
  frame.stats.projective = std::move(projective.stats);
  return frame;
}

}  // namespace frame
