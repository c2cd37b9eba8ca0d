// Mesh repairs and conversions: normals, winding, strips and fans, validity checks (see mesh_ops.h).
#include "scenes/mesh_ops.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <utility>

namespace scenes {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Finite, not near zero, and normalizable in float: a squared length that overflows made glm::normalize
// return (0, 0, 0) (n times 1 / sqrt(inf)), which lit the model black.
bool usable_normal(const glm::vec3& n) {
  const float d = glm::dot(n, n);
  return finite(n) && std::isfinite(d) && d > 1e-12f;
}

void push_unless_degenerate(std::vector<uint32_t>& out, uint32_t a, uint32_t b, uint32_t c) {
  if (a == b || b == c || a == c) return;
  out.insert(out.end(), {a, b, c});
}

}  // namespace

std::vector<glm::vec3> compute_normals(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
  std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
    const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    if (!finite(n)) continue;
    sum[a] += n;
    sum[b] += n;
    sum[c] += n;
  }
  // A model beyond about 1e9 m overflows the float sums' squares, and one below about 1e-6 m falls under
  // usable_normal's floor: those vertices are summed again in double (area weights up to 1e76, down to 1e-300),
  // so that a model lit at 1 m is lit alike at 1e10 m or 1e-10 m. Elsewhere the float sums stand as they were.
  bool all_usable = true;
  for (const glm::vec3& n : sum) all_usable = all_usable && usable_normal(n);
  std::vector<glm::dvec3> wide;
  if (!all_usable) {
    wide.assign(positions.size(), glm::dvec3(0.0));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
      if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
      const glm::dvec3 pa(positions[a]);
      const glm::dvec3 n = glm::cross(glm::dvec3(positions[b]) - pa, glm::dvec3(positions[c]) - pa);
      wide[a] += n, wide[b] += n, wide[c] += n;
    }
  }
  for (size_t i = 0; i < sum.size(); ++i) {
    glm::vec3& n = sum[i];
    if (usable_normal(n)) {
      n = glm::normalize(n);
    } else if (const double len = glm::length(wide[i]); len > 0.0 && std::isfinite(len)) {
      n = glm::vec3(wide[i] / len);
    } else {
      n = glm::vec3(0.0f, 1.0f, 0.0f);
    }
  }
  return sum;
}

size_t repair_normals(Mesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size()) {
    mesh.normals = compute_normals(mesh.positions, mesh.indices);
    return 0;
  }
  size_t bad = 0;
  for (const glm::vec3& n : mesh.normals) bad += usable_normal(n) ? 0 : 1;
  if (bad == 0) return 0;
  const std::vector<glm::vec3> computed = compute_normals(mesh.positions, mesh.indices);
  for (size_t i = 0; i < mesh.normals.size(); ++i)
    if (!usable_normal(mesh.normals[i])) mesh.normals[i] = computed[i];
  return bad;
}

void flip_winding(Mesh& mesh) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

std::vector<uint32_t> strip_to_list(std::span<const uint32_t> strip) {
  std::vector<uint32_t> out;
  if (strip.size() < 3) return out;
  out.reserve((strip.size() - 2) * 3);
  for (size_t i = 0; i + 2 < strip.size(); ++i) {
    const size_t odd = i % 2;
    push_unless_degenerate(out, strip[i], strip[i + 1 + odd], strip[i + 2 - odd]);
  }
  return out;
}

std::vector<uint32_t> fan_to_list(std::span<const uint32_t> fan) {
  std::vector<uint32_t> out;
  if (fan.size() < 3) return out;
  out.reserve((fan.size() - 2) * 3);
  for (size_t i = 0; i + 2 < fan.size(); ++i) push_unless_degenerate(out, fan[i + 1], fan[i + 2], fan[0]);
  return out;
}

bool has_triangle_with_area(const Mesh& m, const glm::mat4& transform) {
  auto at = [&](size_t i) { return glm::vec3(transform * glm::vec4(m.positions[m.indices[i]], 1.0f)); };
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const glm::vec3 a = at(t), n = glm::cross(at(t + 1) - a, at(t + 2) - a);
    if (glm::dot(n, n) > 0.0f) return true;
  }
  return false;
}

std::optional<std::string> mesh_problem(const Mesh& mesh) {
  if (mesh.positions.empty() || mesh.indices.empty()) return "empty mesh (no triangles)";
  if (mesh.indices.size() % 3 != 0)
    return "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3";
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!finite(mesh.positions[i])) return "vertex " + std::to_string(i) + " has a non-finite position";
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      return "index " + std::to_string(i) + " is " + std::to_string(mesh.indices[i]) + ", out of range for " +
             std::to_string(mesh.positions.size()) + " vertices";
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    return std::to_string(mesh.normals.size()) + " normals for " + std::to_string(mesh.positions.size()) +
           " vertices";
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != mesh.positions.size())
    return std::to_string(mesh.texcoords.size()) + " texture coordinates for " +
           std::to_string(mesh.positions.size()) + " vertices";
  return std::nullopt;
}

}  // namespace scenes
