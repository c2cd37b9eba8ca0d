// Coverage of the raster pipeline: watertightness, the tie rule on constructed edges, bounding boxes.
#include <gtest/gtest.h>

#include <random>

#include "raster/renderer.h"
#include "tests/support.h"

using namespace raster;

namespace {

// Clip-space position of window point (x, y) on a W×H target, at NDC depth z.
glm::vec4 win_to_clip(float x, float y, int w, int h, float z = 0.0f) {
  return {x / w * 2.0f - 1.0f, y / h * 2.0f - 1.0f, z, 1.0f};
}

// Renders with depth func ALWAYS and no depth write into a colour target counting coverage via blending is
// not available; instead count coverage with a depth pass: each covered pixel gets depth 0 from 1.
int count_covered(const DepthTarget& d) {
  int n = 0;
  for (int y = 0; y < d.height(); ++y)
    for (int x = 0; x < d.width(); ++x) n += d.value(x, y) < 1.0f;
  return n;
}

}  // namespace

TEST(Coverage, FullScreenQuadCoversEveryPixelOnce) {
  Renderer r(testsupport::test_threads());
  DepthTarget d(37, 23, DepthFormat::d32f);
  std::vector<glm::vec4> v = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
  std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
  auto stats = r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(v), idx);
  EXPECT_EQ(stats.setups, 2u);
  EXPECT_EQ(count_covered(d), 37 * 23);
  EXPECT_EQ(d.value(5, 5), 0.5f);
}
