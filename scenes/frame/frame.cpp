// render_frame: every light resolved and planned through the technique registry, its maps built; the projective
// lights' per-caster maps; then the camera pass, one draw per instance (plus the projective receiver passes),
// each light read through its LightShadow. export_maps turns the built maps into EXR records (see frame.h).
#include "scenes/frame/frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include <glm/matrix.hpp>

#include "raster/parallel_clear.h"
#include "raster/quad_path_only.h"
#include "scenes/camera_math.h"
#include "scenes/frame/camera_shader.h"
#include "scenes/frame/camera_surface.h"
#include "scenes/frame/develop.h"
#include "scenes/frame/frame_lights.h"
#include "shading/techniques/param_use.h"
#include "scenes/frame/projective_shaders.h"
#include "scenes/io/scene_textures.h"
#include "scenes/scene_queries.h"
#include "shading/techniques/depth_pass.h"
#include "shading/techniques/view_frustum.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

tech::Box to_box(const scenes::Aabb& a) { return tech::Box{a.min, a.max}; }

// The casters of every depth pass, flattened once per frame: opaque triangles in one soup, masked ones per
// material with their alpha test (tech::CasterGeometry); instances whose material hides them entirely are left
// out.
struct FrameCasters {
  scenes::CoverageSoup soup;
  std::vector<std::vector<tech::MaskedVertex>> vertices;
  std::vector<tech::MaskedCasters> masked;  // points into `vertices`, `soup` and the frame's surfaces

  FrameCasters(const scenes::Scene& scene, std::span<const shading::SurfaceTexture> surfaces)
      : soup(scenes::flatten_by_coverage(scene, scenes::InstanceFilter::casters)) {
    vertices.resize(soup.masked.size());
    for (size_t k = 0; k < soup.masked.size(); ++k) {
      const scenes::MaskedSoup& m = soup.masked[k];
      vertices[k].resize(m.positions.size());
      for (size_t i = 0; i < m.positions.size(); ++i) vertices[k][i] = {m.positions[i], m.texcoords[i]};
      masked.push_back({vertices[k], m.indices, &surfaces[m.material]});
    }
  }
  FrameCasters(const FrameCasters&) = delete;
  FrameCasters& operator=(const FrameCasters&) = delete;
  tech::CasterGeometry geometry() const { return {soup.opaque.positions, soup.opaque.indices, masked}; }
};

// The camera as the view-following techniques see it.
tech::CameraView camera_view(const scenes::Camera& camera, float aspect) {
  tech::CameraView v;
  v.view = scenes::view_matrix(camera);
  v.proj = scenes::projection_matrix(camera, aspect);
  v.eye = camera.position;
  const glm::vec3 f = camera.target - camera.position;
  v.forward = glm::length(f) > 0.0f ? glm::normalize(f) : glm::vec3(0.0f, 0.0f, -1.0f);
  std::visit([&](const auto& p) { v.near = p.near, v.far = p.far; }, camera.projection);
  v.perspective = std::holds_alternative<scenes::Perspective>(camera.projection);
  return v;
}

// What the camera sees (tech::VisibleSamples): a depth-only pass of the receivers at the frame's size, reduced
// to the range of window depths of each 8×8 tile's covered pixels, taken to view distances (monotonic in window
// depth, so the two ends suffice).
tech::VisibleSamples visible_samples(const scenes::Scene& scene, const glm::mat4& view_proj,
                                     const tech::CameraView& cam, int width, int height, raster::Renderer& renderer) {
  const scenes::TriangleSoup receivers = scenes::flatten(scene, scenes::InstanceFilter::receivers);
  raster::DepthTarget depth(width, height, raster::DepthFormat::d24);
  depth.clear(1.0f);
  raster::DrawState s;
  s.color_write = false;
  renderer.draw(raster::RenderTargets{&depth, nullptr}, s, tech::WorldDepthShader{view_proj},
                std::span<const glm::vec3>(receivers.positions), std::span<const uint32_t>(receivers.indices));
  const glm::mat4 inv_proj = glm::inverse(cam.proj);
  auto distance = [&](float window_z) {
    const glm::vec4 v = inv_proj * glm::vec4(0.0f, 0.0f, 2.0f * window_z - 1.0f, 1.0f);
    return -v.z / v.w;
  };
  constexpr int kTile = 8;
  tech::VisibleSamples v;
  v.min_distance = std::numeric_limits<float>::infinity();
  v.max_distance = -v.min_distance;
  for (int ty = 0; ty < height; ty += kTile)
    for (int tx = 0; tx < width; tx += kTile) {
      float lo = 1.0f, hi = 0.0f;
      for (int y = ty; y < std::min(ty + kTile, height); ++y)
        for (int x = tx; x < std::min(tx + kTile, width); ++x) {
          const float z = depth.value(x, y);
          if (z < 1.0f) lo = std::min(lo, z), hi = std::max(hi, z);
        }
      if (lo > hi) continue;
      tech::VisibleTile t;
      t.ndc_min = {2.0f * float(tx) / float(width) - 1.0f, 2.0f * float(ty) / float(height) - 1.0f};
      t.ndc_max = {2.0f * float(std::min(tx + kTile, width)) / float(width) - 1.0f,
                   2.0f * float(std::min(ty + kTile, height)) / float(height) - 1.0f};
      t.near = distance(lo);
      t.far = distance(hi);
      v.min_distance = std::min(v.min_distance, t.near);
      v.max_distance = std::max(v.max_distance, t.far);
      v.tiles.push_back(t);
    }
  if (v.tiles.empty()) v.min_distance = v.max_distance = 0.0f;
  return v;
}

}  // namespace

Frame render_frame(const scenes::Scene& scene, const FrameConfig& config, raster::Renderer& renderer,
                   FrameCache* cache, const scenes::io::SceneTextures* textures) {
  if (config.width < 1 || config.height < 1 || config.width > 16384 || config.height > 16384)
    throw FrameError("size: " + std::to_string(config.width) + "x" + std::to_string(config.height) +
                     " is outside 1..16384");
  if (!scene.cameras.empty() && config.camera >= scene.cameras.size())
    throw FrameError("camera: index " + std::to_string(config.camera) + " is out of range (the scene has " +
                     std::to_string(scene.cameras.size()) + ")");
  const float aspect = float(config.width) / float(config.height);
  const scenes::Camera camera =
      scene.cameras.empty() ? scenes::frame_camera(scenes::scene_bounds(scene)) : scene.cameras[config.camera];
  const glm::mat4 view_proj = scenes::projection_matrix(camera, aspect) * scenes::view_matrix(camera);

  // ---- Every light resolved before anything is drawn: a bad setting fails the frame before any work.
  std::vector<ResolvedLight> resolved;
  const scenes::Aabb bounds = scenes::scene_bounds(scene);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    resolved.push_back(resolve_light(scene.lights[i], i, config));
    resolved.back().light.ambient = ambient_illuminance(scene.lights[i], bounds);
  }
  for (const auto& [key, value] : config.params)
    if (auto why = unread_override(resolved, key, value)) throw FrameError(*why);
  std::vector<std::string> warnings;
  for (size_t i = 0; i < resolved.size(); ++i)
    if (auto w = moment_receiver_warning(resolved[i], i, scene)) warnings.push_back(std::move(*w));

  // ---- Material textures: the caller's (loaded once per scene), or loaded here for this frame alone; a missing
  // or unreadable file fails the frame before any work.
  std::optional<scenes::io::SceneTextures> own_textures;
  if (!textures) textures = &own_textures.emplace(scenes::io::load_scene_textures(scene));
  const std::vector<shading::SurfaceTexture> surfaces = scenes::io::surface_textures(scene, *textures);

  const float given_ev100 = config.exposure.value_or(scene.look.exposure).ev100.value_or(0.0f);
  if (!std::isfinite(given_ev100) || std::abs(given_ev100) > 64.0f)
    throw FrameError("exposure: EV100 " + std::to_string(given_ev100) + " is outside -64..64");
  // The picture and radiance a recycled frame left in the cache when their size fits, else new ones.
  auto reuse = [&](std::optional<raster::ColorTarget>* kept, raster::ColorFormat format) {
    if (kept && *kept && (*kept)->width() == config.width && (*kept)->height() == config.height) {
      raster::ColorTarget t = std::move(**kept);
      kept->reset();
      return t;
    }
    return raster::ColorTarget(config.width, config.height, format, format == raster::ColorFormat::rgba8);
  };
  Frame frame{reuse(cache ? &cache->picture : nullptr, raster::ColorFormat::rgba8),
              reuse(cache ? &cache->radiance : nullptr, raster::ColorFormat::rgba32f)};

  // ---- Shadow maps, light by light, through the registry.
  const auto t_shadow = Clock::now();
  std::optional<FrameCasters> casters;          // flattened once, when a light first needs them
  std::optional<tech::PlanInputs> inputs;       // scene bounds, computed once
  std::optional<tech::VisibleSamples> visible;  // the camera's depth pre-pass, run when a technique asks
  std::optional<tech::CameraSurface> surface;   // the camera's visible surface, run when a technique asks
  std::vector<ProjectiveLight> projective_lights;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    ResolvedLight& r = resolved[i];
    LightResult lr;
    lr.name = name_stem("light" + std::to_string(i), scene.lights[i].name);
    lr.technique = r.config.technique;
    const tech::TechniqueImpl* impl = tech::find_impl(r.config.technique);
    if (!impl) throw FrameError("lights[" + std::to_string(i) + "].shadow.technique: " +
                                tech::refusal(r.config.technique, scene.lights[i].type));
    if (impl->application == tech::Application::receiver_passes) {
      projective_lights.push_back({i, r.config});
    } else if (impl->application == tech::Application::light_visibility) {
      if (!inputs) {
        inputs.emplace();
        inputs->casters = to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::casters));
        inputs->receivers = tech::camera_receiver_box(
            view_proj, to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::receivers)));
        inputs->scene_receivers = to_box(scenes::scene_bounds(scene, scenes::InstanceFilter::receivers));
        inputs->camera_view_proj = view_proj;
        inputs->eye = camera.position;
        inputs->camera = camera_view(camera, aspect);
        inputs->visible = [&, cam = inputs->camera]() -> const tech::VisibleSamples& {
          if (!visible) visible = visible_samples(scene, view_proj, cam, config.width, config.height, renderer);
          return *visible;
        };
        // Instance boxes only for a light whose fit works object by object (each costs a pass over its mesh).
        const bool per_object = std::any_of(resolved.begin(), resolved.end(), [](const ResolvedLight& l) {
          const auto fit = l.config.params.find("fit");
          return fit != l.config.params.end() && fit->second == tech::ParamValue(std::string("tutorial"));
        });
        if (per_object) inputs->objects.reserve(scene.instances.size());
        for (size_t k = 0; per_object && k < scene.instances.size(); ++k)
          inputs->objects.push_back({to_box(scenes::instance_bounds(scene, k)), scene.instances[k].casts_shadows,
                                     scene.instances[k].receives_shadows});
        inputs->surface = [&]() -> const tech::CameraSurface& {
          if (!surface) surface = camera_surface(scene, surfaces, view_proj, camera.position, config.width, config.height, renderer);
          return *surface;
        };
      }
      inputs->fit_memory = cache ? &cache->fits[i] : nullptr;
      if (!casters) casters.emplace(scene, surfaces);
      try {
        lr.shadow = impl->plan(r.desc, r.config, *inputs);
      } catch (const tech::TechniqueError& e) {
        const std::string what = e.what();
        // Messages that name a light field get the light's place in front; parameter messages already have it
        // (the light's "lights[i].shadow.params.<key>", or an override's "params.<key>", the CLI's option).
        const bool named = what.rfind("lights[", 0) == 0 || what.rfind("params.", 0) == 0;
        throw FrameError(named ? what : "lights[" + std::to_string(i) + "]." + what);
      }
      frame.stats.draws += lr.shadow->build(renderer, casters->geometry());
      ++frame.stats.maps_rendered;
    }
    frame.lights.push_back(std::move(lr));
  }
  // Per-caster projective maps (frame_projective.h), from the cache where nothing changed.
  FrameCache local_cache;
  frame.projective = prepare_projective(scene, projective_lights, config.export_maps,
                                        ProjectiveView{view_proj, config.width, config.height}, renderer,
                                        (cache ? *cache : local_cache).projective, surfaces);
  frame.stats.maps_rendered += frame.projective.stats.maps_rebuilt;
  frame.stats.shadow_ms = ms_since(t_shadow);

  // ---- Camera pass.
  const auto t_camera = Clock::now();
  std::vector<LightRecord> records;
  for (size_t i = 0; i < frame.lights.size(); ++i) records.push_back({resolved[i].light, frame.lights[i].shadow.get()});

  std::optional<raster::DepthTarget> own_depth;
  std::optional<raster::DepthTarget>& depth_slot = cache ? cache->camera_depth : own_depth;
  if (!depth_slot || depth_slot->width() != config.width || depth_slot->height() != config.height)
    depth_slot.emplace(config.width, config.height, raster::DepthFormat::d24);
  raster::DepthTarget& depth = *depth_slot;
  depth.clear(1.0f);                      // pending: each tile is cleared by the draw that first touches it
  raster::clear_on_workers(frame.radiance, glm::vec4(0.0f), renderer.pool());  // alpha 0: the background shows
  std::vector<std::vector<CameraVertex>> mesh_vertices(scene.meshes.size());
  std::vector<std::vector<TexturedCameraVertex>> mesh_textured(scene.meshes.size());  // textured draws only
  frame.view_proj = view_proj;
  frame.eye = camera.position;
  frame.warnings = std::move(warnings);
  if (config.surface_record) frame.surface.emplace(config.width, config.height, scene.lights.size());
  {
    CameraShader shader;
    shader.lights = records;
    shader.record = frame.surface ? &*frame.surface : nullptr;
    shader.u.view_proj = view_proj;
    shader.u.eye = camera.position;
    for (size_t index = 0; index < scene.instances.size(); ++index) {
      const scenes::Instance& inst = scene.instances[index];
      const scenes::Mesh& mesh = scene.meshes.at(inst.mesh);
      if (mesh_vertices[inst.mesh].empty()) mesh_vertices[inst.mesh] = camera_vertices(mesh);
      const scenes::Material& mat = scene.materials.at(inst.material);
      const scenes::Coverage coverage = scenes::coverage(mat);
      if (coverage == scenes::Coverage::hidden) continue;  // every fragment's alpha is below the cutoff
      const raster::DrawState s = camera_instance(scene, index, shader.u);  // as the surface pre-pass draws it
      // Drawn once, plus the projective maps overlapping it (projective_shaders.h).
      auto draw = [&](const auto& sh, const auto& vertices) {
        return draw_receiver(renderer, raster::RenderTargets{&depth, &frame.radiance}, s, sh, std::span(vertices),
                             std::span<const uint32_t>(mesh.indices), frame.projective, index,
                             frame.surface ? &*frame.surface : nullptr);
      };
      const shading::SurfaceTexture& surface = surfaces[inst.material];
      if (surface.texture) {  // factor × texture per pixel, on the quad path
        if (mesh_textured[inst.mesh].empty()) mesh_textured[inst.mesh] = textured_vertices(mesh_vertices[inst.mesh], mesh);
        const auto& vertices = mesh_textured[inst.mesh];
        if (coverage == scenes::Coverage::masked)
          frame.stats.draws += draw(BasicCameraShader<true, true>{shader.u, shader.lights, shader.record, &surface}, vertices);
        else
          frame.stats.draws += draw(BasicCameraShader<true, false>{shader.u, shader.lights, shader.record, &surface}, vertices);
      } else {
        const auto& vertices = mesh_vertices[inst.mesh];
        frame.stats.draws += config.quad_fragments ? draw(raster::QuadPathOnly<CameraShader>{shader}, vertices)
                                                   : draw(shader, vertices);
      }
    }
  }
  // ---- The picture: exposure, tone map, background, one sRGB encode.
  const scenes::Exposure exposure = config.exposure.value_or(scene.look.exposure);
  const shading::ToneMap tone_map = config.tone_map.value_or(scene.look.tone_map);
  frame.ev100 = exposure.ev100 ? *exposure.ev100 : metered_ev100(frame.radiance, tone_map, renderer.pool());
  develop_into(frame.color, frame.radiance, frame.ev100, tone_map,
               config.background.value_or(scene.look.background), renderer.pool());
  frame.stats.camera_ms = ms_since(t_camera);
  if (config.aliasing)
    frame.aliasing = measure_aliasing(scene, view_proj, records, mesh_vertices, depth, renderer);
  frame.stats.projective = frame.projective.stats;
  return frame;
}

void recycle(Frame&& frame, FrameCache& cache) {
  cache.radiance.emplace(std::move(frame.radiance));
  cache.picture.emplace(std::move(frame.color));
}

std::vector<NamedMap> export_maps(const Frame& frame) {
  std::vector<NamedMap> out;
  for (const LightResult& l : frame.lights) {
    if (!l.shadow) continue;
    const std::vector<tech::MapRecord> records = l.shadow->maps();
    for (size_t k = 0; k < records.size(); ++k) {
      const tech::MapRecord& r = records[k];
      scenes::io::ExrMap e = scenes::io::exr_map_from(*r.target);
      if (!r.values.empty()) e.z = r.values;
      e.technique = r.technique;
      e.encoding = r.encoding;
      e.world_to_camera = r.world_to_camera;
      e.world_to_ndc = r.world_to_ndc;
      for (const tech::MapPassRecord& p : r.passes)
        e.passes.push_back(scenes::io::MapPass{p.label, p.viewport, p.world_to_camera, p.world_to_ndc});
      out.push_back({records.size() == 1 ? l.name : l.name + "-" + std::to_string(k), std::move(e)});
    }
  }
  for (size_t m = 0; m < frame.projective.maps.size(); ++m)
    out.push_back({frame.projective.map_names[m], frame.projective.maps[m]});
  return out;
}

SHADOWLAB_ISA_END
}  // namespace frame
