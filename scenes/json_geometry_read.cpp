// Reading the geometry parts of a scene document: transforms, built-in primitives and inline meshes
// (see json_geometry_read.h).
#include "scenes/json_geometry_read.h"

#include "scenes/mesh_ops.h"
#include "scenes/primitives.h"

namespace scenes {
namespace {

constexpr uint32_t kMaxSegments = 4096;

uint8_t read_room_sides(const JsonIn& j) {
  uint8_t sides = 0;
  const auto names = room_side_names();
  for (const JsonIn& e : j.items()) {
    const std::string s = e.string();
    size_t i = 0;
    while (i < names.size() && names[i].name != s) ++i;
    if (i == names.size()) e.fail("unknown room side '" + s + "' (known: " + join_names(names) + ")");
    sides |= uint8_t(1u << i);
  }
  return sides;
}

template <typename V, size_t N>
std::vector<V> read_vectors(const JsonIn& j) {
  const std::vector<float> flat = j.numbers();
  if (flat.size() % N != 0) j.fail("expected a flat array of numbers, " + std::to_string(N) + " per vertex");
  std::vector<V> out(flat.size() / N);
  for (size_t i = 0; i < out.size(); ++i)
    for (size_t c = 0; c < N; ++c) out[i][int(c)] = flat[i * N + c];
  return out;
}

}  // namespace

TransformDesc read_transform(const JsonIn& j) {
  j.allow_only({"translate", "rotate", "quaternion", "scale", "matrix"});
  TransformDesc t;
  if (auto m = j.optional("matrix")) {
    for (const char* other : {"translate", "rotate", "quaternion", "scale"})
      if (j.has(other)) m->fail(std::string("cannot be combined with ") + other);
    t.matrix = m->mat4();
    return t;
  }
  read_opt(j, "translate", t.translate);
  read_opt(j, "rotate", t.rotate_deg);
  if (auto q = j.optional("quaternion")) {
    if (j.has("rotate")) q->fail("cannot be combined with rotate");
    const glm::vec4 v = q->vec4();
    if (!(glm::dot(v, v) > 0.0f)) q->fail("expected a non-zero quaternion [x, y, z, w]");
    t.quaternion = glm::quat(v.w, v.x, v.y, v.z);
  }
  if (auto s = j.optional("scale")) {
    if (s->value().is_number()) t.scale = glm::vec3(s->number());
    else if (s->value().is_array() && s->value().size() == 3) t.scale = s->vec3();
    else s->fail("expected an array of 3 numbers");  // a single number (uniform scale) is also accepted
  }
  return t;
}

Shape read_shape(const JsonIn& j) {
  const JsonIn type = j.member("type");
  const std::string name = type.string();
  auto allow = [&](std::initializer_list<std::string_view> keys) { j.allow_only(keys, name + " primitive"); };
  Shape shape;
  if (name == "plane") {
    allow({"type", "size", "segments"});
    PlaneShape s;
    read_opt(j, "size", s.size);
    read_opt(j, "segments", s.segments, 1, kMaxSegments);
    shape = s;
  } else if (name == "box") {
    allow({"type", "size"});
    BoxShape s;
    read_opt(j, "size", s.size);
    shape = s;
  } else if (name == "sphere") {
    allow({"type", "radius", "segments", "rings"});
    SphereShape s;
    read_opt(j, "radius", s.radius);
    read_opt(j, "segments", s.segments, 3, kMaxSegments);
    read_opt(j, "rings", s.rings, 2, kMaxSegments);
    shape = s;
  } else if (name == "cylinder") {
    allow({"type", "radius", "height", "segments", "caps"});
    CylinderShape s;
    read_opt(j, "radius", s.radius);
    read_opt(j, "height", s.height);
    read_opt(j, "segments", s.segments, 3, kMaxSegments);
    read_opt(j, "caps", s.caps);
    shape = s;
  } else if (name == "cone") {
    allow({"type", "radius", "height", "segments", "cap"});
    ConeShape s;
    read_opt(j, "radius", s.radius);
    read_opt(j, "height", s.height);
    read_opt(j, "segments", s.segments, 3, kMaxSegments);
    read_opt(j, "cap", s.cap);
    shape = s;
  } else if (name == "room") {
    allow({"type", "size", "wall", "sides"});
    RoomShape s;
    read_opt(j, "size", s.size);
    read_opt(j, "wall", s.wall);
    if (auto sides = j.optional("sides")) s.sides = read_room_sides(*sides);
    shape = s;
  } else if (name == "terrain") {
    allow({"type", "size", "resolution", "amplitude", "wavelength", "seed"});
    TerrainShape s;
    read_opt(j, "size", s.size);
    read_opt(j, "resolution", s.resolution, 1, kMaxSegments);
    read_opt(j, "amplitude", s.amplitude);
    read_opt(j, "wavelength", s.wavelength);
    read_opt(j, "seed", s.seed, 0, 0xFFFFFFFFu);
    shape = s;
  } else {
    type.fail("unknown primitive '" + name + "' (known: " + join_names(primitive_names()) + ")");
  }
  if (auto problem = check_shape(shape)) {
    const size_t colon = problem->find(": ");
    j.fail_at(problem->substr(0, colon), problem->substr(colon + 2));
  }
  return shape;
}

Mesh read_mesh(const JsonIn& j) {
  j.allow_only({"name", "positions", "normals", "texcoords", "indices"}, "inline mesh");
  Mesh m;
  read_opt(j, "name", m.name);
  m.positions = read_vectors<glm::vec3, 3>(j.member("positions"));
  if (auto n = j.optional("normals")) m.normals = read_vectors<glm::vec3, 3>(*n);
  if (auto t = j.optional("texcoords")) m.texcoords = read_vectors<glm::vec2, 2>(*t);
  if (auto idx = j.optional("indices")) {
    const auto items = idx->items();
    m.indices.reserve(items.size());
    for (const JsonIn& e : items) m.indices.push_back(e.integer(0, 0xFFFFFFFEu));
  } else {
    for (uint32_t i = 0; i < m.positions.size(); ++i) m.indices.push_back(i);
  }
  if (auto problem = mesh_problem(m)) j.fail(*problem);
  return m;
}

}  // namespace scenes
