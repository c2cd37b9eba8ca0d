// Shimmer between two slightly different frames (see shimmer.h).
#include "scenes/reference/shimmer.h"

#include <cmath>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "scenes/reference/frame_reference.h"
#include "scenes/scene_queries.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

namespace {

glm::vec3 rotate(glm::vec3 v, float degrees, glm::vec3 axis) {
  return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

}  // namespace

scenes::Scene moved(const scenes::Scene& scene, size_t camera, int frame_height, const Motion& motion) {
  scenes::Scene s = scene;
  if (motion.camera_pixels != 0.0f && camera < s.cameras.size()) {
    scenes::Camera& c = s.cameras[camera];
    const glm::vec3 forward = c.target - c.position;
    const float distance = glm::length(forward);
    float world_per_pixel = 0.0f;
    if (const auto* p = std::get_if<scenes::Perspective>(&c.projection))
      world_per_pixel = 2.0f * distance * std::tan(glm::radians(p->fovy_deg) * 0.5f) / float(frame_height);
    else if (const auto* o = std::get_if<scenes::Orthographic>(&c.projection))
      world_per_pixel = (o->top - o->bottom) / float(frame_height);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 offset = right * (motion.camera_pixels * world_per_pixel);
    c.position += offset;
    c.target += offset;
  }
  if (motion.light_degrees != 0.0f) {
    const glm::vec3 centre = scenes::scene_bounds(scene).center();
    for (scenes::Light& l : s.lights) {
      if (l.type == scenes::LightType::directional || l.type == scenes::LightType::spot) {
        glm::vec3 axis = glm::cross(l.direction, glm::vec3(0.0f, 1.0f, 0.0f));
        if (glm::length(axis) < 1e-3f) axis = glm::cross(l.direction, glm::vec3(1.0f, 0.0f, 0.0f));
        l.direction = glm::normalize(rotate(l.direction, motion.light_degrees, axis));
      } else {
        // About the horizontal x axis: a light above the centre (the usual ceiling lamp) moves too.
        l.position = centre + rotate(l.position - centre, motion.light_degrees, glm::vec3(1.0f, 0.0f, 0.0f));
        l.direction = glm::normalize(rotate(l.direction, motion.light_degrees, glm::vec3(1.0f, 0.0f, 0.0f)));
      }
    }
  }
  return s;
}

std::vector<LightShimmer> compare_frames(const frame::SurfaceRecord& r0, const ExactVisibility& e0,
                                         const frame::SurfaceRecord& r1, const ExactVisibility& e1, float shadow_below) {
  if (r0.width != r1.width || r0.height != r1.height || r0.lights != r1.lights || e0.lights != r0.lights ||
      e1.lights != r1.lights || e0.width != r0.width || e1.width != r1.width || e0.height != r0.height ||
      e1.height != r1.height)
    throw ReferenceError("reference: the two frames compared for shimmer differ in size or lights");
  const size_t L = r0.lights;
  std::vector<LightShimmer> out(L);
  for (size_t p = 0; p < r0.pixels(); ++p) {
    if (!r0.covered[p] || !r1.covered[p]) continue;
    for (size_t l = 0; l < L; ++l) {
      const size_t i = p * L + l;
      if (!r0.lit_facing[i] || !r1.lit_facing[i]) continue;
      LightShimmer& s = out[l];
      ++s.compared;
      const bool t_flip = (r0.visibility[i] < shadow_below) != (r1.visibility[i] < shadow_below);
      const bool e_flip = bool(e0.reached[i] && e0.visible[i]) != bool(e1.reached[i] && e1.visible[i]);
      s.flips += t_flip;
      s.exact_flips += e_flip;
      s.shimmering += t_flip && !e_flip;
    }
  }
  return out;
}

std::vector<LightShimmer> shimmer(const scenes::Scene& scene, const frame::FrameConfig& config,
                                  raster::Renderer& renderer, const Motion& motion, const ScoreOptions& options) {
  const scenes::Scene other = moved(scene, config.camera, config.height, motion);
  const FrameReference ref0 = reference_for(scene, config, renderer), ref1 = reference_for(other, config, renderer);
  const ScoredFrame f0 = score_config(scene, config, renderer, ref0, options);
  const ScoredFrame f1 = score_config(other, config, renderer, ref1, options);
  return compare_frames(*f0.frame.surface, ref0.exact, *f1.frame.surface, ref1.exact, options.shadow_below);
}

SHADOWLAB_ISA_END
}  // namespace reference
