// The light frame of the omnidirectional techniques (see omni.h).
#include "shading/techniques/omni.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

LightFrame light_frame(glm::vec3 origin, glm::vec3 forward) {
  LightFrame f;
  f.origin = origin;
  f.z = glm::normalize(forward);
  const glm::vec3 ref = std::fabs(f.z.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  f.y = glm::normalize(ref - f.z * glm::dot(ref, f.z));
  f.x = glm::cross(f.z, f.y);
  return f;
}

glm::mat4 LightFrame::matrix() const {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c) {
    m[c][0] = x[c];
    m[c][1] = y[c];
    m[c][2] = z[c];
  }
  m[3] = glm::vec4(-glm::dot(x, origin), -glm::dot(y, origin), -glm::dot(z, origin), 1.0f);
  return m;
}

OmniReader omni_reader_base(OmniKind kind, const LightFrame& frame, const OmniLight& light, const OmniSettings& s) {
  OmniReader r;
  r.kind = kind;
  r.frame = frame;
  r.position = light.position;
  r.direction = light.direction;
  r.range = light.range;
  r.hemispherical = light.hemispherical;
  r.bias = s.bias;
  r.filter_kind = s.filter;
  r.filter = s.filter_params;
  return r;
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
