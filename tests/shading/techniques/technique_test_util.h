// Helpers for the technique tests: small world-space scenes (a plane, a square occluder, a tilted plane), a classic
// map planned, built and wrapped in a reader in one call, the same map filtered into moments, and the camera over
// a floor that the cascade tests look through.
#pragma once
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec3.hpp>

#include "shading/techniques/classic.h"
#include "shading/techniques/filtered.h"
#include "shading/techniques/technique.h"

namespace techtest {

struct Soup {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  // A counter-clockwise (seen from +normal side) quad a, b, c, d.
  void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const auto base = uint32_t(positions.size());
    positions.insert(positions.end(), {a, b, c, d});
    indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  // A horizontal square [x0, x1] × [z0, z1] at height y, facing up.
  void horizontal(float x0, float x1, float z0, float z1, float y) {
    quad({x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0});
  }
};

// A map and its reader; the set is heap-held so the reader's views stay valid.
struct Built {
  std::unique_ptr<shading::tech::ShadowMapSet> set;
  shading::tech::ClassicReader reader;
};

inline Built build_classic(raster::Renderer& r, const Soup& soup, const shading::tech::ClassicLight& light,
                           const shading::tech::ClassicSettings& s, const shading::tech::ClassicFit& fit) {
  Built b;
  b.set = std::make_unique<shading::tech::ShadowMapSet>(shading::tech::plan_classic_map(light, s, fit));
  shading::tech::build_maps(r, *b.set, shading::tech::CasterGeometry{soup.positions, soup.indices, {}}, shading::tech::classic_depth_options(s));
  b.reader = shading::tech::make_classic_reader(*b.set, light, s);
  return b;
}

// A classic map filtered into moments (filter_classic_map), with no bias and d32f depth.
struct FilteredBuilt {
  std::unique_ptr<shading::tech::ShadowMapSet> set;
  shading::tech::FilteredMap map;
};

inline FilteredBuilt build_filtered(raster::Renderer& r, const Soup& soup, const shading::tech::ClassicLight& light,
                                    const shading::tech::ClassicFit& fit, int map_size,
                                    const shading::tech::MomentParams& m, int radius) {
  shading::tech::ClassicSettings s;
  s.bias.mode = shading::tech::BiasMode::none;
  s.map_size = map_size;
  s.depth_format = raster::DepthFormat::d32f;
  FilteredBuilt f;
  f.set = std::make_unique<shading::tech::ShadowMapSet>(shading::tech::plan_classic_map(light, s, fit));
  shading::tech::build_maps(r, *f.set, shading::tech::CasterGeometry{soup.positions, soup.indices, {}},
                            shading::tech::classic_depth_options(s));
  shading::tech::filter_classic_map(r, *f.set, light, s.bias, m, radius, f.map);
  return f;
}

// A camera at (0, 4, 12) looking down the −z axis and a little down (60° field of view, 3:2, 0.1 to 60 m), over a
// floor at y = 0.
inline shading::tech::CameraView floor_camera() {
  shading::tech::CameraView c;
  c.eye = {0.0f, 4.0f, 12.0f};
  c.forward = glm::normalize(glm::vec3(0.0f, -0.25f, -1.0f));
  c.view = glm::lookAt(c.eye, c.eye + c.forward, glm::vec3(0, 1, 0));
  c.proj = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 60.0f);
  c.near = 0.1f, c.far = 60.0f;
  return c;
}

}  // namespace techtest
