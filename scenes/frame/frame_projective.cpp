// Projective maps for a frame: settings, casters, the cache and the receivers' overlap lists (see
// frame_projective.h).
#include "scenes/frame/frame_projective.h"
#include "scenes/frame/frame_lights.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "scenes/scene_queries.h"
#include "scenes/frame/frame.h"
#include "shading/techniques/fade_table.h"
#include "shading/techniques/tutorial_fit.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

namespace tech = shading::tech;

namespace {

glm::vec3 transform_point(const glm::mat4& m, const glm::vec3& p) {
  return glm::vec3(m[0]) * p.x + glm::vec3(m[1]) * p.y + glm::vec3(m[2]) * p.z + glm::vec3(m[3]);
}

// The world box of an instance from its mesh's model-space box (eight corners transformed): conservative,
// and per instance rather than per vertex.
tech::Box instance_box(const scenes::Aabb& mesh_box, const glm::mat4& m) {
  tech::Box b;
  if (mesh_box.empty()) return b;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p{(i & 1) ? mesh_box.max.x : mesh_box.min.x, (i & 2) ? mesh_box.max.y : mesh_box.min.y,
                      (i & 4) ? mesh_box.max.z : mesh_box.min.z};
    const glm::vec3 w = transform_point(m, p);
    b.min = glm::min(b.min, w), b.max = glm::max(b.max, w);
  }
  return b;
}

// The box of a caster's shadow volume cut `reach` beyond the caster: its box swept along a directional light,
// or its corners pushed `reach` away from a point or spot light. Nullopt when the light is inside the box
// (every direction is shadowed: the volume has no bound worth testing).
std::optional<tech::Box> shadow_volume_box(const tech::ProjectiveLight& light, const tech::Box& caster, float reach) {
  tech::Box v = caster;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p{(i & 1) ? caster.max.x : caster.min.x, (i & 2) ? caster.max.y : caster.min.y,
                      (i & 4) ? caster.max.z : caster.min.z};
    glm::vec3 q;
    if (light.directional) {
      q = p + light.direction * reach;
    } else {
      if (glm::all(glm::greaterThanEqual(light.position, caster.min)) &&
          glm::all(glm::lessThanEqual(light.position, caster.max)))
        return std::nullopt;
      q = p + glm::normalize(p - light.position) * reach;
    }
    v.min = glm::min(v.min, q), v.max = glm::max(v.max, q);
  }
  return v;
}

tech::ProjectiveLight projector_of(const scenes::Light& l) {
  tech::ProjectiveLight p;
  p.directional = l.type == scenes::LightType::directional;
  p.position = l.position;
  p.direction = glm::normalize(l.direction);
  return p;
}

}  // namespace

tech::ProjectiveSettings resolve_projective(const tech::ShadowConfig& c) {
  tech::ProjectiveSettings p;
  p.map_size = c.map_size;
  try {
    const tech::Params params(c);
    p.mode = *tech::parse_projective_mode(params.text("projective_mode"));
    p.caster_shade = float(params.number("caster_shade"));
    p.lod_bias = float(params.number("lod_bias"));
    p.blur_passes = int(params.number("blur_passes"));
    p.blur_offset = float(params.number("blur_offset"));
    p.fade_start = float(params.number("fade_start"));
    p.fade_end = float(params.number("fade_end"));
    if (params.given("fade_end") && p.fade_end != 0.0f && p.fade_end <= p.fade_start)
      throw tech::TechniqueError(params.where("fade_end") + ": must be greater than fade_start (or 0: never fades)");
    if (params.given("fade_start") && p.fade_end == 0.0f)
      throw tech::TechniqueError(params.where("fade_start") + ": has no effect without a fade_end (0: never fades)");
    p.fade_lookup = *tech::parse_fade_lookup(params.text("fade_lookup"));
    if (p.fade_lookup == tech::FadeLookup::texture && !(p.fade_end > p.fade_start))
      throw tech::TechniqueError(params.where("fade_lookup") +
                                 ": texture needs fade_end greater than fade_start (the distances the table spans)");
    std::string why;
    const std::optional<std::vector<float>> table = tech::parse_fade_table(params.text("fade_table"), why);
    if (!table) throw tech::TechniqueError(params.where("fade_table") + ": " + why);
    p.fade_table = *table;
    // Settings that would silently do nothing are refused.
    if (params.given("fade_table") && p.fade_lookup != tech::FadeLookup::texture)
      throw tech::TechniqueError(params.where("fade_table") + ": has no effect unless fade_lookup is texture");
    if (params.given("blur_offset") && p.blur_passes == 0)
      throw tech::TechniqueError(params.where("blur_offset") + ": has no effect unless blur_passes is above 0");
    p.max_textures = int(params.number("max_textures"));
    if (params.given("max_textures") && p.mode != tech::ProjectiveMode::single_pass)
      throw tech::TechniqueError(params.where("max_textures") + ": has no effect unless projective_mode is single-pass");
    p.decimate = params.flag("decimate");
    p.caster_reach = float(params.number("caster_reach"));
  } catch (const tech::TechniqueError& e) {
    throw FrameError(e.what());
  }
  return p;
}

raster::Rect shadow_scissor(const tech::CasterFrustum& f, const tech::Box& box, const ProjectiveView& view) {
  const raster::Rect all{0, 0, view.width, view.height};
  // The frustum cut at the box's far side: near-plane corners and corners at that depth, from NDC.
  float far_depth = -std::numeric_limits<float>::infinity();
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p{(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                      (i & 4) ? box.max.z : box.min.z};
    far_depth = std::max(far_depth, glm::dot(f.depth_row, glm::vec4(p, 1.0f)));
  }
  if (!(far_depth > f.near_depth)) return raster::Rect{};
  const glm::vec4 zc = f.proj * glm::vec4(0.0f, 0.0f, -far_depth, 1.0f);
  const float far_ndc = zc.z / zc.w;
  const glm::mat4 inv = glm::inverse(f.proj * f.view);
  // Window bounds of a set of world points; false when one is not in front of the camera.
  auto bounds = [&](auto&& point, glm::vec2& lo, glm::vec2& hi) {
    lo = glm::vec2(std::numeric_limits<float>::infinity()), hi = -lo;
    for (int i = 0; i < 8; ++i) {
      const glm::vec4 c = view.view_proj * glm::vec4(point(i), 1.0f);
      if (!(c.w > 1e-6f)) return false;
      const glm::vec2 w = (glm::vec2(c.x, c.y) / c.w * 0.5f + 0.5f) * glm::vec2(float(view.width), float(view.height));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
    return true;
  };
  glm::vec2 blo, bhi, flo, fhi;
  const bool box_ok = bounds([&](int i) {
    return glm::vec3{(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z};
  }, blo, bhi);
  const bool frustum_ok = bounds([&](int i) {
    const glm::vec4 w = inv * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? far_ndc : -1.0f, 1.0f);
    return glm::vec3(w) / w.w;
  }, flo, fhi);
  if (!box_ok && !frustum_ok) return all;
  glm::vec2 lo = box_ok ? blo : flo, hi = box_ok ? bhi : fhi;
  if (box_ok && frustum_ok) lo = glm::max(blo, flo), hi = glm::min(bhi, fhi);
  // Whole pixels, one pixel of margin, clamped to the viewport.
  const int x0 = std::max(0, int(std::floor(std::max(lo.x, -1.0f))) - 1);
  const int y0 = std::max(0, int(std::floor(std::max(lo.y, -1.0f))) - 1);
  const int x1 = std::min(view.width, int(std::ceil(std::min(hi.x, float(view.width) + 1.0f))) + 1);
  const int y1 = std::min(view.height, int(std::ceil(std::min(hi.y, float(view.height) + 1.0f))) + 1);
  if (x1 <= x0 || y1 <= y0) return raster::Rect{};
  return raster::Rect{x0, y0, x1 - x0, y1 - y0};
}

ProjectiveFrame prepare_projective(const scenes::Scene& scene, std::span<const ProjectiveLight> lights,
                                   bool export_maps, const ProjectiveView& view, raster::Renderer& renderer,
                                   tech::ProjectiveCache& cache, std::span<const shading::SurfaceTexture> surfaces) {
  ProjectiveFrame pf;
  pf.overlaps.resize(scene.instances.size());
  pf.stats.receiver_draws.assign(scene.instances.size(), 0);
  cache.begin_frame();

  // Per mesh, computed once per frame and only when a projective light needs them.
  std::vector<std::optional<uint64_t>> mesh_hash(scene.meshes.size());
  std::vector<std::optional<scenes::Aabb>> mesh_box(scene.meshes.size());
  auto hash_of = [&](uint32_t m) {
    if (!mesh_hash[m]) mesh_hash[m] = tech::mesh_content_hash(scene.meshes[m].positions, scene.meshes[m].indices);
    return *mesh_hash[m];
  };
  auto box_of = [&](uint32_t m) -> const scenes::Aabb& {
    if (!mesh_box[m]) mesh_box[m] = scenes::mesh_bounds(scene.meshes[m]);
    return *mesh_box[m];
  };
  // Casting instances grouped by top-level object, in scene order.
  std::vector<std::vector<uint32_t>> by_object(scene.objects.size());
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scenes::Instance& inst = scene.instances[i];
    if (!inst.casts_shadows) continue;
    if (inst.object >= by_object.size()) by_object.resize(inst.object + 1);
    by_object[inst.object].push_back(i);
  }

  bool first = true;
  for (const ProjectiveLight& pl : lights) {
    const size_t li = pl.index;
    const scenes::Light& light = scene.lights[li];
    const tech::ProjectiveSettings s = resolve_projective(pl.config);
    pf.stats.active = true;
    // The mode and the textures per draw hold for every receiver of the frame: lights that ask for others are
    // refused rather than overruled by the first.
    if (first) {
      pf.mode = s.mode, pf.max_textures = s.max_textures, first = false;
    } else if (s.mode != pf.mode || s.max_textures != pf.max_textures) {
      const tech::Params p(pl.config);
      throw FrameError(p.where(s.mode != pf.mode ? "projective_mode" : "max_textures") +
                       ": differs from the first projective light's (one mode and one count of textures per draw "
                       "serve the whole frame)");
    }
    const tech::ProjectiveLight projector = projector_of(light);
    // One fade texture per light, shared by its casters' readers.
    const shading::Texture2D fade_table = s.fade_lookup == tech::FadeLookup::texture && s.fade_end > s.fade_start
                                              ? tech::make_fade_texture(s.fade_table)
                                              : shading::Texture2D{};
    for (uint32_t obj = 0; obj < by_object.size(); ++obj) {
      const std::vector<uint32_t>& members = by_object[obj];
      if (members.empty()) continue;
      std::vector<tech::CasterInstanceKey> keys;
      for (uint32_t i : members) {
        const scenes::Instance& inst = scene.instances[i];
        keys.push_back({inst.transform, tech::caster_shade_for(s.caster_shade, scene.materials[inst.material].base_color.a),
                        hash_of(inst.mesh)});
      }
      const uint64_t id = (uint64_t(li) << 32) | obj;
      // The article's "near the view frustum": the caster's shadow volume, cut at caster_reach, meets it.
      if (s.caster_reach > 0.0f) {
        tech::Box box;
        for (uint32_t i : members) {
          const tech::Box b = instance_box(box_of(scene.instances[i].mesh), scene.instances[i].transform);
          box.min = glm::min(box.min, b.min), box.max = glm::max(box.max, b.max);
        }
        const std::optional<tech::Box> volume = shadow_volume_box(projector, box, s.caster_reach);
        if (volume && !tech::box_in_frustum(view.view_proj, *volume)) {
          cache.keep(id);
          ++pf.stats.maps_skipped;
          continue;
        }
      }
      auto map = cache.get(id, tech::make_caster_key(projector, s, keys), [&] {
        // Rebuilding: the caster's exact world bounds and world-space parts, one per instance.
        std::vector<tech::CasterPart> parts;
        tech::Box bounds;
        for (size_t k = 0; k < members.size(); ++k) {
          const scenes::Instance& inst = scene.instances[members[k]];
          const scenes::Mesh& mesh = scene.meshes[inst.mesh];
          const scenes::Coverage coverage = scenes::coverage(scene.materials[inst.material]);
          if (coverage == scenes::Coverage::hidden) continue;
          tech::CasterPart part;
          if (coverage == scenes::Coverage::masked && inst.material < surfaces.size()) {
            part.alpha = &surfaces[inst.material];
            part.texcoords = mesh.texcoords;
          }
          part.positions.reserve(mesh.positions.size());
          for (const glm::vec3& p : mesh.positions) {
            part.positions.push_back(transform_point(inst.transform, p));
            bounds.min = glm::min(bounds.min, part.positions.back());
            bounds.max = glm::max(bounds.max, part.positions.back());
          }
          part.indices = mesh.indices;
          part.shade = keys[k].shade;
          parts.push_back(std::move(part));
        }
        return tech::build_caster_map(renderer, projector, s, bounds, parts);
      });
      if (export_maps) {
        scenes::io::ExrMap e = scenes::io::exr_map_from(*map->target, 0);
        e.world_to_camera = map->frustum.view;
        e.world_to_ndc = map->frustum.proj * map->frustum.view;
        e.technique = "projective";
        e.depth_format = "d32f";  // the mask as floats; there is no depth buffer
        e.encoding = tech::info(tech::Technique::projective).encoding;
        pf.maps.push_back(std::move(e));
        const std::string object_name = obj < scene.objects.size() ? scene.objects[obj] : "object";
        pf.map_names.push_back(name_stem(name_stem("light" + std::to_string(li), light.name) + "-caster" +
                                             std::to_string(obj),
                                         object_name));
      }
      if (!map->frustum.valid) continue;
      AppliedCaster c;
      c.reader = tech::make_projective_reader(*map, s, fade_table);
      c.map = std::move(map);
      c.light = li;
      c.object = obj;
      pf.casters.push_back(std::move(c));
    }
  }
  cache.end_frame();
  pf.stats.maps_rebuilt = cache.rebuilt();
  pf.stats.maps_reused = cache.reused();
  if (pf.casters.empty()) return pf;

  // Receivers: each instance's box against every caster's frustum (never its own object's). A receiver inside
  // a caster's own box (furniture in a room) is not behind that caster as far as boxes can tell: a whole-object
  // silhouette would blacken it, so it is left out.
  auto inside = [](const tech::Box& in, const tech::Box& out) {
    return glm::all(glm::greaterThanEqual(in.min, out.min)) && glm::all(glm::lessThanEqual(in.max, out.max));
  };
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scenes::Instance& inst = scene.instances[i];
    if (!inst.receives_shadows) continue;
    const tech::Box box = instance_box(box_of(inst.mesh), inst.transform);
    for (uint32_t c = 0; c < pf.casters.size(); ++c) {
      const tech::CasterFrustum& f = pf.casters[c].map->frustum;
      if (pf.casters[c].object == inst.object || inside(box, pf.casters[c].map->bounds) || !tech::box_overlaps(f, box))
        continue;
      const raster::Rect scissor = shadow_scissor(f, box, view);
      if (scissor.width > 0) pf.overlaps[i].push_back({c, scissor});
    }
  }
  return pf;
}

SHADOWLAB_ISA_END
}  // namespace frame
