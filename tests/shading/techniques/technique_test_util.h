// Helpers for the technique tests: small world-space scenes (a plane, a square occluder, a tilted plane) and a
// classic map planned, built and wrapped in a reader in one call.
#pragma once
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/techniques/classic.h"

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

}  // namespace techtest
