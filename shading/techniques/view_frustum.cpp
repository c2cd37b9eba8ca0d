// Cutting the camera's frustum into view-distance ranges and slices (see view_frustum.h).
#include "shading/techniques/view_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

float view_distance(const CameraView& c, glm::vec3 p) { return glm::dot(p - c.eye, c.forward); }

ViewRange receiver_view_range(const CameraView& c, const Box& receivers) {
  ViewRange r{c.near, c.far};
  if (receivers.empty()) return r;
  // The view distances of the part of the frustum inside the box; the box's own corners where the two do not
  // meet (nothing the camera sees receives, and the range only has to be valid).
  std::vector<glm::vec3> points = clip_slice_to_box(slice_corners(c, c.near, c.far), receivers);
  if (points.empty()) {
    const auto corners = box_corners(receivers);
    points.assign(corners.begin(), corners.end());
  }
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const glm::vec3& p : points) {
    const float d = view_distance(c, p);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  // Widened by a thousandth of its length each way: the clipped vertices carry the rounding of the planes.
  const float pad = 0.001f * (hi - lo);
  r.near = std::clamp(lo - pad, c.near, c.far);
  r.far = std::clamp(hi + pad, c.near, c.far);
  if (!(r.far > r.near * 1.0001f)) r.far = std::min(c.far, r.near * 1.0001f + 1e-4f);
  return r;
}

ViewRange visible_view_range(const CameraView& c, const VisibleSamples& v) {
  if (v.tiles.empty()) return {c.near, c.far};
  const float pad = 0.01f * (v.max_distance - v.min_distance) + 1e-4f;
  ViewRange r{std::clamp(v.min_distance - pad, c.near, c.far), std::clamp(v.max_distance + pad, c.near, c.far)};
  if (!(r.far > r.near)) r.far = r.near * 1.0001f + 1e-4f;
  return r;
}

std::vector<float> practical_splits(float n, float f, int m, float lambda) {
  std::vector<float> c(size_t(m) + 1);
  for (int i = 0; i <= m; ++i) {
    const float t = float(i) / float(m);
    const float log_split = n * std::pow(f / n, t);
    const float uniform_split = n + (f - n) * t;
    c[size_t(i)] = lambda * log_split + (1.0f - lambda) * uniform_split;
  }
  c.front() = n;  // exact ends, whatever the rounding of pow
  c.back() = f;
  return c;
}

std::array<glm::vec3, 8> slice_corners(const CameraView& c, float a, float b) {
  const glm::mat4 inv_proj = glm::inverse(c.proj), inv_view = glm::inverse(c.view);
  std::array<glm::vec3, 8> out;
  const glm::vec2 xy[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (size_t k = 0; k < 4; ++k) {
    // The frustum edge through this corner, in view space, from the near to the far clip plane.
    glm::vec4 pn = inv_proj * glm::vec4(xy[k], -1.0f, 1.0f), pf = inv_proj * glm::vec4(xy[k], 1.0f, 1.0f);
    const glm::vec3 n3 = glm::vec3(pn) / pn.w, f3 = glm::vec3(pf) / pf.w;
    auto at = [&](float d) {  // the point of the edge at view distance d (view z = −d), linear along the edge
      const float t = (d - (-n3.z)) / ((-f3.z) - (-n3.z));
      return glm::vec3(inv_view * glm::vec4(n3 + (f3 - n3) * t, 1.0f));
    };
    out[k] = at(a);
    out[k + 4] = at(b);
  }
  return out;
}

void visible_body(const CameraView& c, const VisibleSamples& v, float a, float b, std::vector<glm::vec3>& out) {
  const glm::mat4 inv_proj = glm::inverse(c.proj), inv_view = glm::inverse(c.view);
  for (const VisibleTile& t : v.tiles) {
    const float lo = std::max(a, t.near), hi = std::min(b, t.far);
    if (lo > hi) continue;
    for (int k = 0; k < 4; ++k) {
      const glm::vec2 xy((k & 1) ? t.ndc_max.x : t.ndc_min.x, (k & 2) ? t.ndc_max.y : t.ndc_min.y);
      // The ray through this corner, in view space, from the near to the far clip plane (as slice_corners).
      const glm::vec4 pn = inv_proj * glm::vec4(xy, -1.0f, 1.0f), pf = inv_proj * glm::vec4(xy, 1.0f, 1.0f);
      const glm::vec3 n3 = glm::vec3(pn) / pn.w, f3 = glm::vec3(pf) / pf.w;
      for (const float d : {lo, hi}) {
        const float s = (d + n3.z) / (n3.z - f3.z);
        out.push_back(glm::vec3(inv_view * glm::vec4(n3 + (f3 - n3) * s, 1.0f)));
      }
    }
  }
}

std::vector<glm::vec3> clip_slice_to_box(const std::array<glm::vec3, 8>& c, const Box& box) {
  std::vector<glm::vec3> out;
  if (box.empty()) return out;
  // The slice's six planes, normals pointing inwards (towards its centroid).
  constexpr int kFace[6][3] = {{0, 1, 2}, {4, 6, 5}, {0, 3, 4}, {1, 5, 2}, {0, 4, 1}, {3, 2, 7}};
  constexpr int kEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4},
                                {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  glm::vec3 centroid(0.0f);
  for (const glm::vec3& p : c) centroid += p / 8.0f;
  std::array<glm::vec4, 6> planes;
  float scale = 0.0f;
  for (const glm::vec3& p : c) scale = std::max(scale, glm::length(p - centroid));
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 a = c[size_t(kFace[f][0])], b = c[size_t(kFace[f][1])], d = c[size_t(kFace[f][2])];
    glm::vec3 n = glm::cross(b - a, d - a);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f);
    if (glm::dot(n, centroid - a) < 0.0f) n = -n;
    planes[size_t(f)] = glm::vec4(n, -glm::dot(n, a));
  }
  const float eps = 1e-5f * std::max(scale, 1e-3f);
  const glm::vec3 lo = box.min - eps, hi = box.max + eps;
  auto in_box = [&](glm::vec3 p) { return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi)); };
  auto in_slice = [&](glm::vec3 p) {
    for (const glm::vec4& pl : planes)
      if (glm::dot(glm::vec3(pl), p) + pl.w < -eps) return false;
    return true;
  };
  for (const glm::vec3& p : c)
    if (in_box(p)) out.push_back(p);
  const std::array<glm::vec3, 8> bc = box_corners(box);
  for (const glm::vec3& p : bc)
    if (in_slice(p)) out.push_back(p);
  // Slice edges across the box's faces.
  for (const auto& e : kEdge) {
    const glm::vec3 a = c[size_t(e[0])], b = c[size_t(e[1])];
    for (int axis = 0; axis < 3; ++axis)
      for (const float plane : {box.min[axis], box.max[axis]}) {
        const float da = a[axis] - plane, db = b[axis] - plane;
        if ((da < 0.0f) == (db < 0.0f) || da == db) continue;
        glm::vec3 p = a + (b - a) * (da / (da - db));
        p[axis] = plane;
        if (in_box(p)) out.push_back(p);
      }
  }
  // Box edges across the slice's faces.
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis) {
      if (i & (1 << axis)) continue;
      const glm::vec3 a = bc[size_t(i)], b = bc[size_t(i | (1 << axis))];
      for (const glm::vec4& pl : planes) {
        const float da = glm::dot(glm::vec3(pl), a) + pl.w, db = glm::dot(glm::vec3(pl), b) + pl.w;
        if ((da < 0.0f) == (db < 0.0f) || da == db) continue;
        const glm::vec3 p = a + (b - a) * (da / (da - db));
        if (in_slice(p)) out.push_back(p);
      }
    }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
