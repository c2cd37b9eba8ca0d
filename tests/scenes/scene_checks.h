// Test helper: properties every built scene must have, checked triangle by triangle: world-space winding that
// agrees with the vertex normals (front faces counter-clockwise, facing where the normals point).
#pragma once
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace testsupport {

// Fraction of non-degenerate triangles whose world-space geometric normal (from the winding) points the same
// way as the sum of their world-space vertex normals.
inline double winding_agreement(const scenes::Scene& scene) {
  size_t agree = 0, total = 0;
  for (const scenes::Instance& inst : scene.instances) {
    const scenes::Mesh& mesh = scene.meshes[inst.mesh];
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 p[3], n(0.0f);
      for (int k = 0; k < 3; ++k) {
        const uint32_t i = mesh.indices[t + size_t(k)];
        p[k] = glm::vec3(inst.transform * glm::vec4(mesh.positions[i], 1.0f));
        n += normal_matrix * mesh.normals[i];
      }
      const glm::vec3 g = glm::cross(p[1] - p[0], p[2] - p[0]);
      if (glm::length(g) < 1e-12f || glm::length(n) < 1e-6f) continue;
      ++total;
      agree += glm::dot(g, n) > 0.0f ? 1 : 0;
    }
  }
  return total ? double(agree) / double(total) : 1.0;
}

}  // namespace testsupport
