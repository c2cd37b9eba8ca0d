// PCSS's estimate and filter, and the technique around them (see pcss.h).
#include "shading/techniques/pcss.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shading/lookup.h"
#include "shading/techniques/depth_pass.h"
#include "shading/techniques/poisson.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

glm::vec2 pcss_search_radius(const PcssReader& r, float ref) {
  if (!r.depth.perspective) return r.scale * (ref * r.range * r.tan_half);
  // The light's disc seen from the receiver, cut at view distance zs: the map's near plane, but no nearer to
  // the light than a quarter of the receiver's distance (a blocker nearer than that would spread its penumbra
  // over more than three light radii; the 16 taps are better spent nearer the receiver).
  const float z = r.depth.distance(ref);
  const float zs = std::max(r.near, 0.25f * z);
  return r.scale * (r.radius / (2.0f * zs) * std::max(z - zs, 0.0f) / z);
}

glm::vec2 pcss_filter_radius(const PcssReader& r, float ref, float blocker) {
  glm::vec2 k;
  if (!r.depth.perspective) {
    k = r.scale * ((ref - blocker) * r.range * r.tan_half);
  } else {
    const float zr = r.depth.distance(ref), zb = r.depth.distance(blocker);
    k = r.scale * ((zr - zb) / zb * r.radius / (2.0f * zr));
  }
  return glm::max(k, r.texel);
}

glm::vec2 receiver_gradient(const PcssReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 st, float z) {
  // The depth of the plane where the light's ray through map point q meets it.
  auto depth_at = [&](glm::vec2 q, float& out) {
    const glm::vec4 a4 = r.unshadow * glm::vec4(q, 0.0f, 1.0f), b4 = r.unshadow * glm::vec4(q, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(a4) / a4.w, b = glm::vec3(b4) / b4.w;
    const float den = glm::dot(n, b - a);
    if (!(std::abs(den) > 1e-12f)) return false;
    const glm::vec3 x = a + (b - a) * (glm::dot(n, p - a) / den);
    const glm::vec4 c = r.classic.shadow * glm::vec4(x, 1.0f);
    out = c.z / c.w;
    return std::isfinite(out);
  };
  glm::vec2 g(0.0f);
  float zx, zy;
  if (depth_at(st + glm::vec2(r.texel.x, 0.0f), zx)) g.x = (zx - z) / r.texel.x;
  if (depth_at(st + glm::vec2(0.0f, r.texel.y), zy)) g.y = (zy - z) / r.texel.y;
  const glm::vec2 lim = glm::vec2(0.01f) / r.texel;
  return glm::clamp(g, -lim, lim);
}

float pcss_visibility(const PcssReader& r, glm::vec3 p, glm::vec3 n, glm::vec2 frag) {
  SampleContext c;
  if (!classic_context(r.classic, p, n, frag, c)) return 0.0f;
  // The receiver's own depth where p projects (the reference before the bias), and its plane's gradient.
  const glm::vec3 q = r.classic.bias.mode == BiasMode::normal ? p + n * r.classic.bias.normal_offset : p;
  const glm::vec4 h = r.classic.shadow * glm::vec4(q, 1.0f);
  const glm::vec2 grad = receiver_gradient(r, q, n, c.st, h.z / h.w);
  // A hardware PCF tap compares the four texels around it, up to a texel from the tap: the plane's rise over
  // one texel is allowed on top, so a plane facing the light at a slant does not shadow itself between them.
  const float slack = std::abs(grad.x) * r.texel.x + std::abs(grad.y) * r.texel.y;
  c.ref -= slack;
  const glm::vec2 rot = rotation_of(pixel_seed(frag));
  auto disc = [&](int i) {
    const glm::vec2 d = kPoissonDisk[size_t(i)];
    return glm::vec2(rot.x * d.x - rot.y * d.y, rot.y * d.x + rot.x * d.y);
  };
  // Blocker search: texels nearer to the light than the receiver, nearest texel per tap; outside the map none.
  const TextureLevel& L = r.map.level(0);
  const glm::vec2 search = pcss_search_radius(r, c.ref);
  float sum = 0.0f;
  int blockers = 0;
  for (int i = 0; i < 16; ++i) {
    const glm::vec2 off = disc(i) * search;
    const glm::vec2 st = c.st + off;
    const int x = int(std::floor(st.x * L.fwidth)), y = int(std::floor(st.y * L.fheight));
    if (x < 0 || y < 0 || x >= L.width || y >= L.height) continue;
    const float z = decode_texel(r.map.format(), L.row(y), x).r;
    if (z < c.ref + glm::dot(grad, off)) sum += z, ++blockers;
  }
  if (blockers == 0) return 1.0f;  // early exit: nothing can hide the light
  const glm::vec2 kernel = pcss_filter_radius(r, c.ref, sum / float(blockers));
  float vis = 0.0f;
  for (int i = 0; i < 16; ++i) {
    const glm::vec2 off = disc(i) * kernel;
    vis += r.classic.maps.linear(glm::vec3(c.st + off, c.ref + glm::dot(grad, off)));
  }
  return vis / 16.0f;
}

PcssReader make_pcss_reader(const ShadowMapSet& set, const ClassicLight& light, const ClassicSettings& settings,
                            float size, size_t pass) {
  const ShadowPass& p = set.passes.at(pass);
  PcssReader r;
  r.classic = make_classic_reader(set, light, settings, pass);
  r.map = Texture2D::view(*set.targets.at(p.target), p.viewport);
  r.depth = LightDepth::of(p.proj, p.perspective);
  r.texel = glm::vec2(1.0f / float(p.viewport.width), 1.0f / float(p.viewport.height));
  r.unshadow = glm::inverse(r.classic.shadow);
  if (p.perspective) {
    r.radius = size;
    r.near = r.depth.distance(0.0f);
    r.scale = glm::vec2(p.proj[0][0], p.proj[1][1]);
  } else {
    r.tan_half = std::tan(0.5f * size * 3.14159265358979f / 180.0f);
    r.range = 2.0f / std::abs(p.proj[2][2]);
    r.scale = glm::vec2(p.proj[0][0], p.proj[1][1]) * 0.5f;
  }
  return r;
}

namespace {

class PcssShadow final : public LightShadow {
 public:
  PcssShadow(const ClassicLight& light, const ClassicSettings& settings, const ClassicFit& fit, float size)
      : light_(light), settings_(settings), set_(plan_classic_map(light, settings, fit)), size_(size) {}

  raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& c) override {
    const raster::DrawStats stats =
        build_maps(renderer, set_, c, classic_depth_options(settings_));
    r_ = make_pcss_reader(set_, light_, settings_, size_);
    return stats;
  }
  void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const override {
    for (size_t i = 0; i < q.size(); ++i) vis[i] = pcss_visibility(r_, q[i].p, q[i].n, q[i].frag);
  }
  bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const override {
    return one_pass_texels(set_, r_.classic.shadow, p, others, out);
  }
  std::vector<MapRecord> maps() const override { return {one_pass_record(set_, Technique::pcss)}; }

 private:
  ClassicLight light_;
  ClassicSettings settings_;
  ShadowMapSet set_;
  float size_;
  PcssReader r_;
};

}  // namespace

std::unique_ptr<LightShadow> plan_pcss(const LightDesc& light, const ShadowConfig& c, const PlanInputs& in) {
  const ClassicLight l = classic_light(light);
  const ClassicSettings s = classic_settings(c);
  const ClassicFit fit{in.receivers, in.casters, std::nullopt};
  const Params p(c);
  const float size = float(l.kind == LightKind::spot ? p.number("light_radius") : p.number("light_angle"));
  return std::make_unique<PcssShadow>(l, s, fit, size);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
