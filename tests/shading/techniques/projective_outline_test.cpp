// A box caster over a plane under a directional light: the projective map's shadow outline on the plane
// matches the classic depth-map technique's (a 4096² d32f map, hard filter) within one texel of the
// projective map measured on the plane, at every map size the test tries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shading/techniques/projective_lookup.h"
#include "tests/shading/techniques/technique_test_util.h"
#include "tests/support.h"

using namespace shading::tech;

namespace {

struct Span1 {
  float lo = 1e9f, hi = -1e9f;
};

TEST(ProjectiveOutline, MatchesTheDepthMapWithinOneTexel) {
  raster::Renderer r(testsupport::test_threads());
  const glm::vec3 dir = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
  const glm::vec3 lo(-0.5f, 1.0f, -0.5f), hi(0.5f, 2.0f, 0.5f);
  techtest::Soup box;  // six faces, counter-clockwise from outside
  box.quad({lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});  // top
  box.quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z});  // bottom
  box.quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});  // +z
  box.quad({hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z});  // -z
  box.quad({hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z});  // +x
  box.quad({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});  // -x

  // Classic: the plane's box as receivers, the box as the only caster.
  ClassicSettings cs;
  cs.filter = FilterKind::hard;
  cs.bias.mode = BiasMode::none;
  cs.map_size = 4096;
  cs.depth_format = raster::DepthFormat::d32f;
  ClassicFit fit;
  fit.receivers = Box{{-3.0f, 0.0f, -3.0f}, {3.0f, 0.0f, 3.0f}};
  fit.casters = Box{lo, hi};
  const auto classic = techtest::build_classic(r, box, {LightKind::directional, {}, dir}, cs, fit);

  CasterPart part{box.positions, box.indices, 0.0f};
  const glm::vec3 centre = glm::vec3(0.0f, 1.5f, 0.0f) + dir * (1.5f / -dir.y);  // shadow centre on y = 0
  float worst = 0.0f;
  for (int size : {16, 31, 64, 128, 255}) {
    ProjectiveSettings ps;
    ps.map_size = size;
    const CasterMap m = build_caster_map(r, {true, {}, dir}, ps, Box{lo, hi}, std::span(&part, 1));
    const ProjectiveReader rd = make_projective_reader(m, ps);
    // One texel of the map on the plane y = 0: the Jacobian of (s, t) over (x, z), inverted.
    const glm::mat2 j(glm::vec2(m.frustum.texgen[0][0], m.frustum.texgen[0][1]),
                      glm::vec2(m.frustum.texgen[2][0], m.frustum.texgen[2][1]));
    const glm::mat2 ji = glm::inverse(j);
    const float texel = std::max(glm::length(ji * glm::vec2(1.0f / float(size), 0.0f)),
                                 glm::length(ji * glm::vec2(0.0f, 1.0f / float(size))));
    // Two scan lines through the shadow's centre, along x and along z.
    for (int axis : {0, 2}) {
      Span1 a, b;
      for (int k = -6000; k <= 6000; ++k) {
        glm::vec3 p = centre;
        p[axis] += float(k) * 0.0005f;
        p.y = 0.0f;
        const float vc = classic_visibility<HardFilter, false>(classic.reader, p, {0, 1, 0}, {0, 0});
        const float vp = projective_factors(rd, {p, p, p, p})[0];
        if (vc < 0.5f) a.lo = std::min(a.lo, p[axis]), a.hi = std::max(a.hi, p[axis]);
        if (vp < 0.5f) b.lo = std::min(b.lo, p[axis]), b.hi = std::max(b.hi, p[axis]);
      }
      ASSERT_LT(a.lo, a.hi);
      ASSERT_LT(b.lo, b.hi) << "size " << size;
      const float d = std::max(std::abs(a.lo - b.lo), std::abs(a.hi - b.hi));
      worst = std::max(worst, d / texel);
      EXPECT_LE(d, texel) << "size " << size << " axis " << axis << ": classic [" << a.lo << ", " << a.hi
                          << "], projective [" << b.lo << ", " << b.hi << "], texel " << texel;
    }
  }
  std::printf("projective outline vs depth map: worst %.3f texel of the projective map\n", worst);
}

}  // namespace
