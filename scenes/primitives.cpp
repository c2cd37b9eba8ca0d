// Mesh generators for the built-in primitives (see primitives.h). Every face is emitted counter-clockwise as
// seen from outside; a quad (p0, p1, p2, p3) is listed counter-clockwise and split along p0-p2.
#include "scenes/primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scenes/mesh_ops.h"

namespace scenes {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr uint32_t kMaxSegments = 4096;

// Appends vertices to a mesh and quads or triangles between them.
struct Builder {
  Mesh mesh;

  uint32_t vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(n);
    mesh.texcoords.push_back(uv);
    return uint32_t(mesh.positions.size() - 1);
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c) { mesh.indices.insert(mesh.indices.end(), {a, b, c}); }
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  // A flat rectangle centred on c with half-extent vectors u and v, facing cross(u, v).
  void face(glm::vec3 c, glm::vec3 u, glm::vec3 v) {
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    quad(vertex(c - u - v, n, {0, 0}), vertex(c + u - v, n, {1, 0}), vertex(c + u + v, n, {1, 1}),
         vertex(c - u + v, n, {0, 1}));
  }
  // An axis-aligned closed box between lo and hi.
  void box(glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 c = (lo + hi) * 0.5f, h = (hi - lo) * 0.5f;
    const glm::vec3 x(h.x, 0, 0), y(0, h.y, 0), z(0, 0, h.z);
    face(c + x, -z, y);  // +X
    face(c - x, z, y);   // -X
    face(c + y, x, -z);  // +Y
    face(c - y, x, z);   // -Y
    face(c + z, x, y);   // +Z
    face(c - z, -x, y);  // -Z
  }
  // A disc at height y facing +Y (up = true) or -Y.
  void disc(float radius, float y, uint32_t segments, bool up) {
    const glm::vec3 n(0, up ? 1.0f : -1.0f, 0);
    const uint32_t centre = vertex({0, y, 0}, n, {0.5f, 0.5f});
    const uint32_t first = uint32_t(mesh.positions.size());
    for (uint32_t j = 0; j <= segments; ++j) {
      const float a = kTwoPi * float(j) / float(segments);
      vertex({radius * std::sin(a), y, radius * std::cos(a)}, n,
             {0.5f + 0.5f * std::sin(a), 0.5f + 0.5f * std::cos(a)});
    }
    for (uint32_t j = 0; j < segments; ++j) {
      if (up) triangle(centre, first + j, first + j + 1);
      else triangle(centre, first + j + 1, first + j);
    }
  }
};

// Direction around the Y axis: angle 0 is +Z, increasing towards +X.
glm::vec3 around(float angle) { return {std::sin(angle), 0.0f, std::cos(angle)}; }

Mesh plane(const PlaneShape& s) {
  Builder b;
  const uint32_t n = s.segments, row = n + 1;
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) {
      const float u = float(i) / float(n), v = float(j) / float(n);
      b.vertex({(u - 0.5f) * s.size.x, 0.0f, (v - 0.5f) * s.size.y}, {0, 1, 0}, {u, 1.0f - v});
    }
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = j * row + i;  // (x, z) corner; +Z is towards the viewer looking down -Y
      b.quad(a + row, a + row + 1, a + 1, a);
    }
  return std::move(b.mesh);
}

Mesh sphere(const SphereShape& s) {
  Builder b;
  const uint32_t row = s.segments + 1;
  for (uint32_t i = 0; i <= s.rings; ++i) {
    const float theta = std::numbers::pi_v<float> * float(i) / float(s.rings);
    for (uint32_t j = 0; j <= s.segments; ++j) {
      const float phi = kTwoPi * float(j) / float(s.segments);
      const glm::vec3 n = std::sin(theta) * around(phi) + glm::vec3(0, std::cos(theta), 0);
      b.vertex(s.radius * n, n, {float(j) / float(s.segments), 1.0f - float(i) / float(s.rings)});
    }
  }
  for (uint32_t i = 0; i < s.rings; ++i)
    for (uint32_t j = 0; j < s.segments; ++j) {
      const uint32_t tl = i * row + j, bl = tl + row, br = bl + 1, tr = tl + 1;
      if (i + 1 < s.rings) b.triangle(tl, bl, br);  // the other triangle is degenerate at the poles
      if (i > 0) b.triangle(tl, br, tr);
    }
  return std::move(b.mesh);
}

Mesh cylinder(const CylinderShape& s) {
  Builder b;
  const float h = 0.5f * s.height;
  for (uint32_t j = 0; j <= s.segments; ++j) {
    const glm::vec3 d = around(kTwoPi * float(j) / float(s.segments));
    const float u = float(j) / float(s.segments);
    b.vertex(s.radius * d + glm::vec3(0, h, 0), d, {u, 1});
    b.vertex(s.radius * d - glm::vec3(0, h, 0), d, {u, 0});
  }
  for (uint32_t j = 0; j < s.segments; ++j) b.quad(2 * j, 2 * j + 1, 2 * j + 3, 2 * j + 2);
  if (s.caps) {
    b.disc(s.radius, h, s.segments, true);
    b.disc(s.radius, -h, s.segments, false);
  }
  return std::move(b.mesh);
}

Mesh cone(const ConeShape& s) {
  Builder b;
  const float h = 0.5f * s.height;
  for (uint32_t j = 0; j < s.segments; ++j) {
    const float a0 = kTwoPi * float(j) / float(s.segments), a1 = kTwoPi * float(j + 1) / float(s.segments);
    auto normal = [&](float a) { return glm::normalize(s.height * around(a) + glm::vec3(0, s.radius, 0)); };
    const float u0 = float(j) / float(s.segments), u1 = float(j + 1) / float(s.segments);
    const uint32_t apex = b.vertex({0, h, 0}, normal(0.5f * (a0 + a1)), {0.5f * (u0 + u1), 1});
    const uint32_t p0 = b.vertex(s.radius * around(a0) - glm::vec3(0, h, 0), normal(a0), {u0, 0});
    const uint32_t p1 = b.vertex(s.radius * around(a1) - glm::vec3(0, h, 0), normal(a1), {u1, 0});
    b.triangle(apex, p0, p1);
  }
  if (s.cap) b.disc(s.radius, -h, s.segments, false);
  return std::move(b.mesh);
}

Mesh room(const RoomShape& s) {
  Builder b;
  const float t = s.wall, x = 0.5f * s.size.x, y = s.size.y, z = 0.5f * s.size.z;
  // Floor and ceiling cover the full outer footprint, z walls the full outer width, x walls fit between.
  if (s.sides & room_floor) b.box({-x - t, -t, -z - t}, {x + t, 0, z + t});
  if (s.sides & room_ceiling) b.box({-x - t, y, -z - t}, {x + t, y + t, z + t});
  if (s.sides & room_neg_z) b.box({-x - t, 0, -z - t}, {x + t, y, -z});
  if (s.sides & room_pos_z) b.box({-x - t, 0, z}, {x + t, y, z + t});
  if (s.sides & room_neg_x) b.box({-x - t, 0, -z}, {-x, y, z});
  if (s.sides & room_pos_x) b.box({x, 0, -z}, {x + t, y, z});
  return std::move(b.mesh);
}

Mesh terrain(const TerrainShape& s) {
  PlaneShape grid{s.size, s.resolution};
  Mesh m = plane(grid);
  for (glm::vec3& p : m.positions) p.y = terrain_height(s, p.x, p.z);
  m.normals = compute_normals(m.positions, m.indices);
  return m;
}

// A 32-bit mix (splitmix-like) to derive wave directions and phases from the seed.
float hash01(uint32_t seed, uint32_t k) {
  uint32_t v = seed * 0x9E3779B9u + k * 0x85EBCA6Bu + 0x165667B1u;
  v ^= v >> 16;
  v *= 0x7FEB352Du;
  v ^= v >> 15;
  v *= 0x846CA68Bu;
  v ^= v >> 16;
  return float(v >> 8) / float(1u << 24);
}

std::optional<std::string> positive(const char* key, float v) {
  if (!(v > 0.0f)) return std::string(key) + ": must be positive";
  return std::nullopt;
}

std::optional<std::string> count_in(const char* key, uint32_t v, uint32_t lo) {
  if (v < lo || v > kMaxSegments)
    return std::string(key) + ": must be between " + std::to_string(lo) + " and " + std::to_string(kMaxSegments);
  return std::nullopt;
}

template <typename... Checks>
std::optional<std::string> first_of(Checks... checks) {
  std::optional<std::string> out;
  ((out = out ? out : checks), ...);
  return out;
}

}  // namespace

float terrain_height(const TerrainShape& s, float x, float z) {
  constexpr int kWaves = 4;
  float sum = 0.0f, weights = 0.0f, wavelength = s.wavelength, weight = 1.0f;
  for (int k = 0; k < kWaves; ++k) {
    const float angle = kTwoPi * hash01(s.seed, uint32_t(2 * k));
    const float phase = kTwoPi * hash01(s.seed, uint32_t(2 * k + 1));
    const float along = std::cos(angle) * x + std::sin(angle) * z;
    sum += weight * std::sin(kTwoPi * along / wavelength + phase);
    weights += weight;
    wavelength /= 1.9f;
    weight *= 0.45f;
  }
  return s.amplitude * sum / weights;
}

Mesh make_shape_mesh(const Shape& shape) {
  Mesh m = std::visit(
      [](const auto& s) -> Mesh {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PlaneShape>) return plane(s);
        else if constexpr (std::is_same_v<S, BoxShape>) {
          Builder b;
          b.box(-0.5f * s.size, 0.5f * s.size);
          return std::move(b.mesh);
        } else if constexpr (std::is_same_v<S, SphereShape>) return sphere(s);
        else if constexpr (std::is_same_v<S, CylinderShape>) return cylinder(s);
        else if constexpr (std::is_same_v<S, ConeShape>) return cone(s);
        else if constexpr (std::is_same_v<S, RoomShape>) return room(s);
        else return terrain(s);
      },
      shape);
  m.name = std::string(shape_name(shape));
  return m;
}

std::optional<std::string> check_shape(const Shape& shape) {
  return std::visit(
      [](const auto& s) -> std::optional<std::string> {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PlaneShape>)
          return first_of(positive("size", std::min(s.size.x, s.size.y)), count_in("segments", s.segments, 1));
        else if constexpr (std::is_same_v<S, BoxShape>)
          return positive("size", std::min({s.size.x, s.size.y, s.size.z}));
        else if constexpr (std::is_same_v<S, SphereShape>)
          return first_of(positive("radius", s.radius), count_in("segments", s.segments, 3),
                          count_in("rings", s.rings, 2));
        else if constexpr (std::is_same_v<S, CylinderShape> || std::is_same_v<S, ConeShape>)
          return first_of(positive("radius", s.radius), positive("height", s.height),
                          count_in("segments", s.segments, 3));
        else if constexpr (std::is_same_v<S, RoomShape>) {
          if (s.sides == 0 || s.sides > 63) return std::string("sides: must name at least one side");
          return first_of(positive("size", std::min({s.size.x, s.size.y, s.size.z})), positive("wall", s.wall));
        } else {
          if (!(s.amplitude >= 0.0f)) return std::string("amplitude: must not be negative");
          return first_of(positive("size", std::min(s.size.x, s.size.y)), count_in("resolution", s.resolution, 1),
                          positive("wavelength", s.wavelength));
        }
      },
      shape);
}

}  // namespace scenes
