// Shadow-sampler lookups on llvmpipe: a depth texture with GL_COMPARE_REF_TO_TEXTURE read through
// sampler2DShadow in a fragment shader. sample_shadow evaluates given (s, t, ref) exactly (the reference for
// shading's samplers); time_pcf_pass times full-screen hardware-PCF and Poisson passes for the benchmarks.
#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "raster/reference/gl_reference.h"
#include "raster/reference/gl_util.h"

namespace glref {

namespace {
using namespace detail;

// Best-candidate dart throwing in the unit disk (16 rounds of 400 candidates, fixed seed, best of 200 sets):
// minimum pairwise distance 0.413. The first point is near the centre.
constexpr std::array<float, 32> kPoissonDisk16 = {
    -0.0028f, -0.0072f, -0.2569f, 0.6840f,  0.6892f,  -0.2486f, -0.4786f, -0.5562f,
    -0.7296f, 0.1607f,  0.5094f,  0.5205f,  0.2568f,  -0.7024f, 0.8587f,  0.2055f,
    0.1719f,  0.8308f,  -0.8233f, -0.2964f, 0.4185f,  0.1047f,  -0.0777f, -0.4254f,
    0.1064f,  0.3979f,  -0.6648f, 0.5849f,  -0.4284f, -0.1462f, -0.1494f, -0.8665f};

// A triangle covering the whole viewport, from gl_VertexID alone (no vertex buffer).
constexpr const char* kFullScreenVertexShader = R"(#version 330 core
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Pixel (x, y) of the result target evaluates coordinate number y·width + x, fetched exactly from a float texture.
constexpr const char* kQueryFragmentShader = R"(#version 330 core
uniform sampler2DShadow u_map;
uniform sampler2D u_coords;
layout(location = 0) out float o_result;
void main() {
  vec3 c = texelFetch(u_coords, ivec2(gl_FragCoord.xy), 0).xyz;
  o_result = texture(u_map, c);
}
)";

std::string pcf_pass_shader(int taps) {
  return "#version 330 core\n#define TAPS " + std::to_string(taps) + R"(
uniform sampler2DShadow u_map;
uniform vec2 u_inv_target;   // 1 / target size
uniform vec2 u_radius;       // 2 texels of the map, in texture coordinates
uniform vec2 u_disk[16];
layout(location = 0) out vec4 o_color;
void main() {
  vec2 p = gl_FragCoord.xy * u_inv_target;
  float ref = 0.5 * (p.x + p.y);
#if TAPS == 0
  float lit = ref;  // no lookup: the pass without its texture work
#elif TAPS == 1
  float lit = texture(u_map, vec3(p, ref));
#else
  float lit = 0.0;
  for (int i = 0; i < TAPS; ++i) lit += texture(u_map, vec3(p + u_disk[i] * u_radius, ref));
  lit *= 1.0 / float(TAPS);
#endif
  o_color = vec4(lit, lit, lit, 1.0);
}
)";
}

GLint wrap_mode(Wrap w, Profile profile) {
  switch (w) {
    case Wrap::clamp_to_edge: return GL_CLAMP_TO_EDGE;
    case Wrap::clamp_to_border: return GL_CLAMP_TO_BORDER;
    case Wrap::repeat: return GL_REPEAT;
    case Wrap::mirrored_repeat: return GL_MIRRORED_REPEAT;
    case Wrap::clamp:
      if (profile != Profile::compatibility)
        throw std::runtime_error("glref: legacy GL_CLAMP needs a Context created with Profile::compatibility");
      return 0x2900;  // GL_CLAMP, absent from the core-profile header
  }
  throw std::runtime_error("glref: unknown wrap mode");
}

// Binds a new shadow-compare depth texture holding the query's texels to texture unit 0.
Texture make_shadow_map(const Context::ShadowSampleQuery& q, Profile profile) {
  if (q.tex_width < 1 || q.tex_height < 1 || q.tex_width > 16384 || q.tex_height > 16384)
    throw std::runtime_error("glref: shadow map " + std::to_string(q.tex_width) + "x" +
                             std::to_string(q.tex_height) + " is outside 1..16384");
  Texture tex;
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex.get());
  define_depth_texture(q.format, q.tex_width, q.tex_height, q.texels);
  const GLint filter = q.linear ? GL_LINEAR : GL_NEAREST;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_mode(q.wrap_s, profile));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap_mode(q.wrap_t, profile));
  const float border[4] = {q.border, q.border, q.border, q.border};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GLint(compare_func(q.compare)));
  check_gl("setting up the shadow map");
  return tex;
}

// A colour texture of the given format bound as the only draw buffer of `fbo`, which stays bound.
Texture make_color_target(const Framebuffer& fbo, GLenum internal_format, int width, int height) {
  Texture tex;
  glBindTexture(GL_TEXTURE_2D, tex.get());
  glTexStorage2D(GL_TEXTURE_2D, 1, internal_format, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex.get(), 0);
  const GLenum draw = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &draw);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  check_framebuffer("the colour target");
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  return tex;
}
}  // namespace

std::span<const float, 32> poisson_disk16() { return kPoissonDisk16; }

std::vector<float> Context::sample_shadow(const ShadowSampleQuery& q) {
  make_current();
  if (q.coords.empty()) return {};
  // Results are laid out in rows of 4096 on a target of at most 16384 rows (llvmpipe's largest texture).
  const int n = int(std::min(q.coords.size(), size_t(1) << 26));
  if (size_t(n) != q.coords.size()) throw std::runtime_error("glref: more than 2^26 shadow lookups in one query");
  const int width = std::min(n, 4096);
  const int height = (n + width - 1) / width;

  Texture map = make_shadow_map(q, profile_);
  // The coordinates as an RGBA32F texture, one texel per lookup, fetched without filtering or conversion.
  std::vector<float> packed(size_t(width) * size_t(height) * 4, 0.0f);
  for (int i = 0; i < n; ++i) {
    packed[size_t(i) * 4 + 0] = q.coords[size_t(i)].x;
    packed[size_t(i) * 4 + 1] = q.coords[size_t(i)].y;
    packed[size_t(i) * 4 + 2] = q.coords[size_t(i)].z;
  }
  Texture coords;
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, coords.get());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, packed.data());
  glActiveTexture(GL_TEXTURE0);
  check_gl("uploading shadow lookup coordinates");

  Framebuffer fbo;
  Texture result = make_color_target(fbo, GL_R32F, width, height);
  glBindTexture(GL_TEXTURE_2D, map.get());  // make_color_target left its own texture bound on unit 0
  Program program("shadow lookup", kFullScreenVertexShader, kQueryFragmentShader);
  glUseProgram(program.get());
  glUniform1i(program.uniform("u_map"), 0);
  glUniform1i(program.uniform("u_coords"), 1);
  VertexArray vao;
  glBindVertexArray(vao.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  check_gl("the shadow lookup draw");

  std::vector<float> out(size_t(width) * size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, out.data());
  check_gl("reading shadow lookups");
  out.resize(size_t(n));
  return out;
}

std::vector<double> Context::time_pcf_pass(int width, int height, const ShadowSampleQuery& tex, int taps,
                                           int repeat) {
  make_current();
  if (taps < 0 || taps > 16) throw std::runtime_error("glref: PCF pass taps must be 0..16");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::runtime_error("glref: PCF pass target is outside 1..16384");
  Framebuffer fbo;
  Texture color = make_color_target(fbo, GL_RGBA8, width, height);
  Texture map = make_shadow_map(tex, profile_);
  Program program("PCF pass", kFullScreenVertexShader, pcf_pass_shader(taps));
  glUseProgram(program.get());
  if (taps > 0) glUniform1i(program.uniform("u_map"), 0);
  glUniform2f(program.uniform("u_inv_target"), 1.0f / float(width), 1.0f / float(height));
  if (taps > 1) {
    glUniform2f(program.uniform("u_radius"), 2.0f / float(tex.tex_width), 2.0f / float(tex.tex_height));
    glUniform2fv(program.uniform("u_disk[0]"), 16, kPoissonDisk16.data());
  }
  VertexArray vao;
  glBindVertexArray(vao.get());
  check_gl("setting up the PCF pass");
  return time_frames(3, repeat, [] { glDrawArrays(GL_TRIANGLES, 0, 3); });
}

}  // namespace glref
