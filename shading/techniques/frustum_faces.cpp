// The face-split perspective maps of seed 003: faces, homographies, ownership and reading (see frustum_faces.h).
#include "shading/techniques/frustum_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "shading/techniques/slice_set.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

// A 3×3 projective map of the plane, row-major, in double precision.
struct Homography {
  std::array<std::array<double, 3>, 3> m{};
  glm::dvec3 operator()(glm::dvec2 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2], m[1][0] * p.x + m[1][1] * p.y + m[1][2],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2]};
  }
};

Homography inverse(const Homography& h) {
  const auto& a = h.m;
  Homography r;
  r.m[0] = {a[1][1] * a[2][2] - a[1][2] * a[2][1], a[0][2] * a[2][1] - a[0][1] * a[2][2],
            a[0][1] * a[1][2] - a[0][2] * a[1][1]};
  r.m[1] = {a[1][2] * a[2][0] - a[1][0] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0],
            a[0][2] * a[1][0] - a[0][0] * a[1][2]};
  r.m[2] = {a[1][0] * a[2][1] - a[1][1] * a[2][0], a[0][1] * a[2][0] - a[0][0] * a[2][1],
            a[0][0] * a[1][1] - a[0][1] * a[1][0]};
  return r;  // the adjugate: the inverse up to scale, which a projective map does not see
}

// The map of the unit square onto the quadrilateral q00, q10, q11, q01 (corner (s, t) to q_st), after Heckbert
// (Fundamentals of Texture Mapping, 1989): affine when the quadrilateral is a parallelogram.
Homography square_to_quad(glm::dvec2 q00, glm::dvec2 q10, glm::dvec2 q11, glm::dvec2 q01) {
  const glm::dvec2 s = q00 - q10 + q11 - q01;
  Homography h;
  double g = 0.0, k = 0.0;
  if (std::abs(s.x) > 1e-12 || std::abs(s.y) > 1e-12) {
    const glm::dvec2 d1 = q10 - q11, d2 = q01 - q11;
    const double den = d1.x * d2.y - d2.x * d1.y;
    g = (s.x * d2.y - d2.x * s.y) / den;
    k = (d1.x * s.y - s.x * d1.y) / den;
  }
  h.m[0] = {q10.x - q00.x + g * q10.x, q01.x - q00.x + k * q01.x, q00.x};
  h.m[1] = {q10.y - q00.y + g * q10.y, q01.y - q00.y + k * q01.y, q00.y};
  h.m[2] = {g, k, 1.0};
  return h;
}

// The intersection of line a0-a1 with line b0-b1; false when they are (nearly) parallel.
bool intersect(glm::dvec2 a0, glm::dvec2 a1, glm::dvec2 b0, glm::dvec2 b1, glm::dvec2& out) {
  const glm::dvec2 r = a1 - a0, s = b1 - b0;
  const double den = r.x * s.y - r.y * s.x;
  if (std::abs(den) < 1e-12 * glm::length(r) * glm::length(s)) return false;
  const glm::dvec2 w = b0 - a0;
  out = a0 + r * ((w.x * s.y - w.y * s.x) / den);
  return true;
}

struct FaceDef {
  const char* label;
  std::array<int, 4> corner;  // q00, q10, q11, q01 as slice_corners indices
  bool side;                  // passes through the eye: s runs from the near edge (q00–q01) to the far edge
};
// slice_corners: 0..3 near (−x−y, +x−y, +x+y, −x+y), 4..7 far, same order.
constexpr FaceDef kFaces[6] = {
    {"near", {0, 1, 2, 3}, false}, {"far", {4, 5, 6, 7}, false},  {"left", {0, 4, 7, 3}, true},
    {"right", {1, 5, 6, 2}, true}, {"bottom", {0, 4, 5, 1}, true}, {"top", {3, 7, 6, 2}, true},
};

// A 4×4 whose rows are given over light-view coordinates (u, v, z, 1); glm is column-major.
glm::mat4 from_rows(const std::array<glm::dvec4, 4>& rows) {
  glm::mat4 m(0.0f);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = float(rows[size_t(r)][c]);
  return m;
}

}  // namespace

FacePlan plan_face_maps(glm::vec3 direction, const CameraView& camera, ViewRange range, const Box& casters,
                        int map_size, FaceWarp warp, float guard_texels) {
  const glm::vec3 d = glm::normalize(direction);
  const auto corners = slice_corners(camera, range.near, range.far);
  glm::vec3 centroid(0.0f);
  for (const glm::vec3& c : corners) centroid += c / 8.0f;
  const glm::mat4 view = light_view(d, light_up(d));
  std::array<glm::dvec2, 8> uv;
  double z_low = std::numeric_limits<double>::infinity(), top = -z_low;
  for (size_t i = 0; i < 8; ++i) {
    const glm::vec3 q = glm::vec3(view * glm::vec4(corners[i], 1.0f));
    uv[i] = glm::dvec2(q.x, q.y);
    z_low = std::min(z_low, double(q.z));
    top = std::max(top, double(q.z));
  }
  if (!casters.empty())
    for (const glm::vec3& p : box_corners(casters)) top = std::max(top, double((view * glm::vec4(p, 1.0f)).z));
  const double pad = std::max(top - z_low, 1e-3) * 0.005;
  top += pad, z_low -= pad;
  const double depth_far = top - z_low;
  const double k_guard = 1.0 - 2.0 * double(guard_texels) / double(map_size);

  FacePlan plan;
  for (const FaceDef& f : kFaces) {
    const glm::vec3 a = corners[size_t(f.corner[0])], b = corners[size_t(f.corner[1])],
                    c = corners[size_t(f.corner[3])];
    glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(normal, a - centroid) < 0.0f) normal = -normal;  // outward
    if (!(glm::dot(normal, -d) > 1e-4f)) continue;                // edge-on or facing away: not light-facing
    glm::dvec2 q00 = uv[size_t(f.corner[0])], q10 = uv[size_t(f.corner[1])], q11 = uv[size_t(f.corner[2])],
               q01 = uv[size_t(f.corner[3])];
    if (warp == FaceWarp::lispsm && f.side && camera.perspective) {
      // The legs (q00–q10, q01–q11) meet at the eye as the light sees it. Moving that centre of projection back
      // from the near edge by the factor (n + √(n·f)) / n and taking new near corners on the legs' lines through
      // it widens the near edge: the quadrilateral still covers the face, with a milder warp.
      glm::dvec2 apex;
      if (intersect(q00, q10, q01, q11, apex)) {
        const glm::dvec2 mid = 0.5 * (q00 + q01);
        const double k = 1.0 + std::sqrt(double(range.far) / double(range.near));
        const glm::dvec2 apex2 = mid + (apex - mid) * k;
        glm::dvec2 n0, n1;
        if (intersect(apex2, q10, q00, q01, n0) && intersect(apex2, q11, q00, q01, n1)) q00 = n0, q01 = n1;
      }
    }
    Homography to_square = inverse(square_to_quad(q00, q10, q11, q01));
    // Positive q inside the face.
    const glm::dvec3 mid = to_square(0.25 * (q00 + q10 + q11 + q01));
    if (mid.z < 0.0)
      for (auto& row : to_square.m)
        for (double& x : row) x = -x;
    const auto& r = to_square.m;
    // q's smallest value over the face (at a corner: q is linear in u, v) scales depth into [-1, 1]; 1 % less
    // for the guard band beyond the near edge. Not over the guard band's corners: beyond the far edge an exact
    // warp reaches the line at infinity within a fraction of a texel (s = f / (f − n)), where q changes sign.
    double q_min = std::numeric_limits<double>::infinity();
    for (const glm::dvec2 p : {q00, q10, q11, q01}) q_min = std::min(q_min, r[2][0] * p.x + r[2][1] * p.y + r[2][2]);
    q_min *= 0.99;
    const double alpha = 2.0 * q_min / depth_far;
    const glm::dvec4 s_row(r[0][0], r[0][1], 0.0, r[0][2]), t_row(r[1][0], r[1][1], 0.0, r[1][2]),
        q_row(r[2][0], r[2][1], 0.0, r[2][2]);
    FaceMap m;
    m.label = f.label;
    m.fit.view = view;
    // clip x, y: the face's square scaled into [−k, k] (the guard band outside); z: alpha·(top − z) − q, so
    // depth/q runs from −1 at the casters' top to at most 1 at the lowest frustum point; w: q.
    m.fit.proj = from_rows({k_guard * (2.0 * s_row - q_row), k_guard * (2.0 * t_row - q_row),
                            glm::dvec4(0.0, 0.0, -alpha, alpha * top) - q_row, q_row});
    m.fit.perspective = true;
    m.fit.depth_extent = float(depth_far);
    m.owner = from_rows({s_row, t_row, glm::dvec4(0.0), q_row}) * view;
    plan.faces.push_back(std::move(m));
  }
  return plan;
}

size_t face_owner(const FacePlan& plan, glm::vec3 p, float* margin) {
  size_t best = 0;
  float best_margin = -std::numeric_limits<float>::infinity();
  for (size_t k = 0; k < plan.faces.size(); ++k) {
    const glm::vec4 h = plan.faces[k].owner * glm::vec4(p, 1.0f);
    if (!(h.w > 0.0f)) continue;
    const float s = h.x / h.w, t = h.y / h.w;
    const float m = std::min(std::min(s, 1.0f - s), std::min(t, 1.0f - t));
    if (m > best_margin) best_margin = m, best = k;
  }
  if (margin) *margin = best_margin;
  return best;
}

namespace {

class FaceShadow final : public LightShadow {
 public:
  FaceShadow(FacePlan plan, const LightDesc& light, const ShadowConfig& c, bool atlas)
      : plan_(std::move(plan)), set_(Technique::frustum_faces, fits(plan_), labels(plan_), light, c, atlas) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override { return set_.build(renderer, c); }

  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    const SliceLight& l = set_.light();
    dispatch_filter(l.filter_kind, l.filter.pcf_taps, [&]<class F, bool kPcf>() {
      for (size_t i = 0; i < q.size(); ++i)
        vis[i] = slice_visibility<F, kPcf>(set_.map(face_owner(plan_, q[i].p)), l, q[i]);
    });
  }

  void visibility_x8(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    const SliceLight& l = set_.light();
    dispatch_filter(l.filter_kind, l.filter.pcf_taps, [&]<class F, bool kPcf>() {
      slices_visibility_x8<F, kPcf>(set_.maps(), l, q, [&](size_t i) { return face_owner(plan_, q[i].p); }, vis);
    });
  }

  std::vector<MapRecord> maps() const override { return set_.records(); }

  bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const override {
    return slice_texels(set_.map(face_owner(plan_, p)), p, others, out);
  }

 private:
  static std::vector<FittedMap> fits(const FacePlan& p) {
    std::vector<FittedMap> out;
    for (const FaceMap& f : p.faces) out.push_back(f.fit);
    return out;
  }
  static std::vector<std::string> labels(const FacePlan& p) {
    std::vector<std::string> out;
    for (const FaceMap& f : p.faces) out.push_back(f.label);
    return out;
  }

  FacePlan plan_;
  SliceSet set_;
};

}  // namespace

std::unique_ptr<LightShadow> plan_frustum_faces(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  const Params p(c);
  ViewRange range = receiver_view_range(in.camera, in.receivers);
  if (p.text("view_range") == "visible") {
    if (!in.visible) throw TechniqueError(p.where("view_range") + ": visible needs the camera's depth pre-pass");
    range = visible_view_range(in.camera, in.visible());
  }
  const FaceWarp warp = p.text("face_warp") == "lispsm" ? FaceWarp::lispsm : FaceWarp::exact;
  FacePlan plan = plan_face_maps(light.direction, in.camera, range, in.casters, c.map_size, warp);
  // Issue 23: a scene 10^30 m across left no face, and an empty map set then failed as "width 0".
  if (plan.faces.empty())
    throw TechniqueError("shadow.technique: frustum-faces: the light sees no face of the camera's view frustum "
                         "between the receivers' near and far distances (is the scene's extent beyond a float's?)");
  return std::make_unique<FaceShadow>(std::move(plan), light, c, p.text("map_layout") == "atlas");
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
