// Bounds, triangle counts and world-space triangle soup of a built scene (see scene_queries.h).
#include "scenes/scene_queries.h"

namespace scenes {
namespace {

glm::vec3 transform_point(const glm::mat4& m, const glm::vec3& p) {
  return glm::vec3(m[0]) * p.x + glm::vec3(m[1]) * p.y + glm::vec3(m[2]) * p.z + glm::vec3(m[3]);
}

void append(TriangleSoup& soup, const Scene& scene, const Instance& inst) {
  const Mesh& mesh = scene.meshes[inst.mesh];
  const uint32_t base = uint32_t(soup.positions.size());
  for (const glm::vec3& p : mesh.positions) soup.positions.push_back(transform_point(inst.transform, p));
  for (uint32_t i : mesh.indices) soup.indices.push_back(base + i);
}

// Reserves the soup's whole size once: reserving each instance's share as it is appended would defeat the
// vectors' geometric growth and copy the soup once per instance (quadratic in the instance count).
template <class Pass>
void reserve_for(TriangleSoup& soup, const Scene& scene, size_t count, Pass&& pass) {
  size_t positions = 0, indices = 0;
  for (size_t k = 0; k < count; ++k)
    if (const Instance* inst = pass(k)) {
      positions += scene.meshes[inst->mesh].positions.size();
      indices += scene.meshes[inst->mesh].indices.size();
    }
  soup.positions.reserve(positions);
  soup.indices.reserve(indices);
}

}  // namespace

bool passes(const Instance& instance, InstanceFilter filter) {
  switch (filter) {
    case InstanceFilter::all: return true;
    case InstanceFilter::casters: return instance.casts_shadows;
    case InstanceFilter::receivers: return instance.receives_shadows;
  }
  return true;
}

Aabb mesh_bounds(const Mesh& mesh) {
  Aabb box;
  for (const glm::vec3& p : mesh.positions) box.extend(p);
  return box;
}

Aabb instance_bounds(const Scene& scene, size_t instance) {
  const Instance& inst = scene.instances[instance];
  const Mesh& mesh = scene.meshes[inst.mesh];
  Aabb box;
  for (const glm::vec3& p : mesh.positions) box.extend(transform_point(inst.transform, p));
  return box;
}

Aabb object_bounds(const Scene& scene, uint32_t object) {
  Aabb box;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].object == object) box.extend(instance_bounds(scene, i));
  return box;
}

Aabb scene_bounds(const Scene& scene, InstanceFilter filter) {
  Aabb box;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (passes(scene.instances[i], filter)) box.extend(instance_bounds(scene, i));
  return box;
}

std::vector<uint32_t> object_instances(const Scene& scene, uint32_t object) {
  std::vector<uint32_t> out;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].object == object) out.push_back(uint32_t(i));
  return out;
}

size_t triangle_count(const Scene& scene, InstanceFilter filter) {
  size_t n = 0;
  for (const Instance& inst : scene.instances)
    if (passes(inst, filter)) n += scene.meshes[inst.mesh].triangle_count();
  return n;
}

TriangleSoup flatten(const Scene& scene, InstanceFilter filter) {
  TriangleSoup soup;
  reserve_for(soup, scene, scene.instances.size(), [&](size_t k) {
    return passes(scene.instances[k], filter) ? &scene.instances[k] : nullptr;
  });
  for (const Instance& inst : scene.instances)
    if (passes(inst, filter)) append(soup, scene, inst);
  return soup;
}

Coverage coverage(const Material& m) {
  if (m.alpha_mode == AlphaMode::opaque) return Coverage::opaque;
  if (!m.texture.empty()) return Coverage::masked;
  return m.base_color.a >= alpha_cutoff(m) ? Coverage::opaque : Coverage::hidden;
}

float alpha_cutoff(const Material& m) {
  switch (m.alpha_mode) {
    case AlphaMode::opaque: return 0.0f;
    case AlphaMode::mask: return m.alpha_cutoff;
    case AlphaMode::blend: return 0.5f;
  }
  return 0.0f;
}

CoverageSoup flatten_by_coverage(const Scene& scene, InstanceFilter filter) {
  CoverageSoup out;
  auto cover = [&](const Instance& inst) { return coverage(scene.materials[inst.material]); };
  reserve_for(out.opaque, scene, scene.instances.size(), [&](size_t k) {
    const Instance& inst = scene.instances[k];
    return passes(inst, filter) && cover(inst) == Coverage::opaque ? &inst : nullptr;
  });
  std::vector<int> slot(scene.materials.size(), -1);  // material -> index in out.masked
  for (const Instance& inst : scene.instances) {
    if (!passes(inst, filter)) continue;
    const Coverage c = cover(inst);
    if (c == Coverage::opaque) append(out.opaque, scene, inst);
    if (c != Coverage::masked) continue;
    if (slot[inst.material] < 0) {
      slot[inst.material] = int(out.masked.size());
      out.masked.push_back(MaskedSoup{inst.material, {}, {}, {}});
    }
    MaskedSoup& m = out.masked[size_t(slot[inst.material])];
    const Mesh& mesh = scene.meshes[inst.mesh];
    const uint32_t base = uint32_t(m.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      m.positions.push_back(transform_point(inst.transform, mesh.positions[i]));
      m.texcoords.push_back(i < mesh.texcoords.size() ? mesh.texcoords[i] : glm::vec2(0.0f));
    }
    for (uint32_t i : mesh.indices) m.indices.push_back(base + i);
  }
  return out;
}

TriangleSoup flatten_instances(const Scene& scene, std::span<const uint32_t> instances) {
  TriangleSoup soup;
  reserve_for(soup, scene, instances.size(), [&](size_t k) { return &scene.instances[instances[k]]; });
  for (uint32_t i : instances) append(soup, scene, scene.instances[i]);
  return soup;
}

}  // namespace scenes
