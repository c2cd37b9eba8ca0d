// Scoring a technique's shadow factors against the exact visibility (see shadow_score.h).
#include "scenes/reference/shadow_score.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

namespace {

const float kCreaseCos = std::cos(30.0f * 3.14159265f / 180.0f);

// Sizes of 8-connected groups of set pixels: the largest's count and the longest bounding-box side of any.
void false_lit_groups(const std::vector<uint8_t>& mask, int w, int h, LightScore& s) {
  std::vector<uint8_t> seen(mask.size(), 0);
  std::vector<size_t> stack;
  for (size_t start = 0; start < mask.size(); ++start) {
    if (!mask[start] || seen[start]) continue;
    size_t count = 0;
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    stack.push_back(start);
    seen[start] = 1;
    while (!stack.empty()) {
      const size_t p = stack.back();
      stack.pop_back();
      ++count;
      const int x = int(p % size_t(w)), y = int(p / size_t(w));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const size_t q = size_t(ny) * size_t(w) + size_t(nx);
          if (mask[q] && !seen[q]) seen[q] = 1, stack.push_back(q);
        }
    }
    s.largest_false_lit_group = std::max(s.largest_false_lit_group, count);
    s.longest_false_lit_run = std::max({s.longest_false_lit_run, x1 - x0 + 1, y1 - y0 + 1});
  }
}

}  // namespace

std::vector<uint8_t> exact_boundaries(const frame::SurfaceRecord& r, const ExactVisibility& e, size_t light) {
  const size_t L = e.lights;
  std::vector<uint8_t> b(r.pixels(), 0);
  auto lit = [&](size_t p) { return e.reached[p * L + light] && e.visible[p * L + light]; };
  auto differ = [&](size_t p, size_t q) {
    return r.covered[q] && (lit(p) != lit(q) || glm::dot(r.normal[p], r.normal[q]) < kCreaseCos);
  };
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t p = r.index(x, y);
      if (!r.covered[p]) continue;
      if ((x > 0 && differ(p, p - 1)) || (x + 1 < r.width && differ(p, p + 1)) ||
          (y > 0 && differ(p, p - size_t(r.width))) || (y + 1 < r.height && differ(p, p + size_t(r.width))))
        b[p] = 1;
    }
  return b;
}

std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, int w, int h, int radius) {
  // Separable: a running maximum along rows, then along columns.
  std::vector<uint8_t> rows(mask.size(), 0), out(mask.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t m = 0;
      for (int k = std::max(0, x - radius); k <= std::min(w - 1, x + radius) && !m; ++k) m = mask[size_t(y) * size_t(w) + size_t(k)];
      rows[size_t(y) * size_t(w) + size_t(x)] = m;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t m = 0;
      for (int k = std::max(0, y - radius); k <= std::min(h - 1, y + radius) && !m; ++k) m = rows[size_t(k) * size_t(w) + size_t(x)];
      out[size_t(y) * size_t(w) + size_t(x)] = m;
    }
  return out;
}

FrameScore score_frame(const frame::SurfaceRecord& r, const ExactVisibility& e, const ScoreOptions& o) {
  if (r.width != e.width || r.height != e.height || r.lights != e.lights)
    throw ReferenceError("reference: the frame (" + std::to_string(r.width) + "x" + std::to_string(r.height) + ", " +
                         std::to_string(r.lights) + " lights) and the reference (" + std::to_string(e.width) + "x" +
                         std::to_string(e.height) + ", " + std::to_string(e.lights) + " lights) differ");
  FrameScore out;
  out.errors.assign(r.pixels(), 0);
  const size_t L = r.lights;
  for (size_t l = 0; l < L; ++l) {
    LightScore s;
    const std::vector<uint8_t> near = dilate(exact_boundaries(r, e, l), r.width, r.height, o.near_radius);
    std::vector<uint8_t> false_lit(r.pixels(), 0);
    double abs_sum = 0.0;
    for (size_t p = 0; p < r.pixels(); ++p) {
      const size_t i = p * L + l;
      if (!r.covered[p] || !r.lit_facing[i]) continue;
      if (!e.reached[i]) {
        ++s.unreached;
        continue;
      }
      ++s.scored;
      const float S = r.visibility[i];
      const bool exact_lit = e.visible[i];
      abs_sum += std::fabs(double(S) - (exact_lit ? 1.0 : 0.0));
      const bool shadowed = S < o.shadow_below;
      if (shadowed && exact_lit) {
        (near[p] ? s.false_shadowed_near : s.false_shadowed_elsewhere)++;
        out.errors[p] |= kFalseShadowed;
      } else if (!shadowed && !exact_lit) {
        (near[p] ? s.false_lit_near : s.false_lit_elsewhere)++;
        out.errors[p] |= kFalseLit;
        false_lit[p] = 1;
      }
    }
    s.mean_abs_error = s.scored ? abs_sum / double(s.scored) : 0.0;
    false_lit_groups(false_lit, r.width, r.height, s);
    out.lights.push_back(s);
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace reference
