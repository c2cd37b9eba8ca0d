// Light frustum planning: the automatic directional fit contains its receivers and the casters between them
// and the light; the spot frustum follows the tutorial's numbers; the bias matrix maps clip space to [0, 1].
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/techniques/light_frustum.h"
#include "shading/techniques/shadow_map_set.h"

using namespace shading::tech;

namespace {

glm::vec3 ndc(const LightMatrices& m, glm::vec3 p) {
  const glm::vec4 c = m.proj * m.view * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

bool inside(glm::vec3 v) { return v.x >= -1.001f && v.x <= 1.001f && v.y >= -1.001f && v.y <= 1.001f && v.z >= -1.001f && v.z <= 1.001f; }

TEST(LightFrustum, DirectionalFitHoldsReceiversAndCasters) {
  const Box receivers{{-5, 0, -5}, {5, 1, 5}};
  const Box casters{{-1, 0, -1}, {1, 8, 1}};  // reaches up towards the light
  const LightMatrices m = fit_directional(glm::normalize(glm::vec3(-0.5f, -2, -2)), receivers, casters);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 r((i & 1) ? 5 : -5, (i & 2) ? 1 : 0, (i & 4) ? 5 : -5);
    const glm::vec3 c((i & 1) ? 1 : -1, (i & 2) ? 8 : 0, (i & 4) ? 1 : -1);
    EXPECT_TRUE(inside(ndc(m, r))) << i;
    EXPECT_GT(ndc(m, c).z, -1.001f) << i;  // no caster is clipped by the near plane
  }
}

TEST(LightFrustum, ReceiverBoxIsCameraFrustumCutByScene) {
  const glm::mat4 vp = glm::perspective(glm::radians(45.0f), 1.0f, 0.5f, 1000.0f) *
                       glm::lookAt(glm::vec3(0, 5, 20), glm::vec3(0), glm::vec3(0, 1, 0));
  const Box scene{{-6, 0, -6}, {6, 5, 6}};
  const Box r = camera_receiver_box(vp, scene);
  EXPECT_EQ(r.min, scene.min);
  EXPECT_EQ(r.max, scene.max);
}

TEST(LightFrustum, SpotMatchesTutorial) {
  const LightMatrices m = spot_frustum({5, 20, 20}, -glm::normalize(glm::vec3(0.5f, 2, 2)), glm::radians(22.5f), 50.0f);
  const glm::mat4 expect = glm::perspective(glm::radians(45.0f), 1.0f, 2.0f, 50.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(m.proj[c][r], expect[c][r], 1e-5f);
  EXPECT_NEAR(ndc(m, {0, 0, 0}).x, 0.0f, 1e-4f);
  EXPECT_NEAR(ndc(m, {0, 0, 0}).y, 0.0f, 1e-4f);
}

TEST(ShadowMapSet, BiasMatrixMapsClipToTexture) {
  const glm::vec4 a = bias_matrix() * glm::vec4(-1, -1, -1, 1), b = bias_matrix() * glm::vec4(1, 1, 1, 1);
  EXPECT_EQ(a, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(b, glm::vec4(1, 1, 1, 1));
}

}  // namespace
