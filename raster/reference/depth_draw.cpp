// Depth-only draws on llvmpipe: clip-space triangles into a depth texture attached to a framebuffer object, with
// the fixed-function state of raster::DrawState set through the matching GL calls. Used for depth conformance
// (render_depth) and for llvmpipe's side of the depth benchmarks (time_depth).
#include <stdexcept>
#include <string>

#include "raster/reference/gl_reference.h"
#include "raster/reference/gl_util.h"

namespace glref {

namespace {
using namespace detail;

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
void main() { gl_Position = a_pos; }
)";
constexpr const char* kFragmentShader = R"(#version 330 core
void main() {}
)";

void check_draw(const Context::DepthDraw& d) {
  if (d.width < 1 || d.height < 1 || d.width > 16384 || d.height > 16384)
    throw std::runtime_error("glref: depth target " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                             " is outside 1..16384");
  if (d.clip_positions.size() > size_t(INT32_MAX / 16) || d.indices.size() > size_t(INT32_MAX / 4))
    throw std::runtime_error("glref: too many vertices or indices for one draw");
  for (uint32_t i : d.indices)
    if (i >= d.clip_positions.size())
      throw std::runtime_error("glref: index " + std::to_string(i) + " is past the " +
                               std::to_string(d.clip_positions.size()) + " clip positions");
}

// All GL objects of one depth draw, built once; frame() clears and draws, as often as a benchmark asks.
class DepthPass {
 public:
  explicit DepthPass(const Context::DepthDraw& d) : d_(d), program_("depth-only", kVertexShader, kFragmentShader) {
    check_draw(d);
    glBindTexture(GL_TEXTURE_2D, depth_.get());
    define_depth_texture(d.format, d.width, d.height, {});
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    check_framebuffer("the depth draw");

    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, positions_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(d.clip_positions.size_bytes()), d.clip_positions.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    if (!d.indices.empty()) {
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(d.indices.size_bytes()), d.indices.data(), GL_STATIC_DRAW);
    }
    glUseProgram(program_.get());
    check_gl("uploading the depth draw");
  }

  void clear() const {
    // GL's clear honours the scissor test and the depth mask; the reference clears the whole target.
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glClearDepth(d_.clear_depth);
    glClear(GL_DEPTH_BUFFER_BIT);
  }

  void frame() const {
    clear();
    set_state();
    if (d_.indices.empty())
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(d_.clip_positions.size() / 3 * 3));
    else
      glDrawElements(GL_TRIANGLES, GLsizei(d_.indices.size() / 3 * 3), GL_UNSIGNED_INT, nullptr);
  }

 private:
  void set_state() const {
    const raster::Rect vp = d_.viewport.value_or(raster::Rect{0, 0, d_.width, d_.height});
    glViewport(vp.x, vp.y, vp.width, vp.height);
    glDepthRange(0.0, 1.0);
    if (d_.scissor) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(d_.scissor->x, d_.scissor->y, d_.scissor->width, d_.scissor->height);
    } else {
      glDisable(GL_SCISSOR_TEST);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(compare_func(d_.depth_func));
    glDepthMask(d_.depth_write ? GL_TRUE : GL_FALSE);
    if (d_.cull == raster::CullMode::none) {
      glDisable(GL_CULL_FACE);
    } else {
      glEnable(GL_CULL_FACE);
      glCullFace(d_.cull == raster::CullMode::back ? GL_BACK : GL_FRONT);
    }
    glFrontFace(d_.front_face == raster::FrontFace::ccw ? GL_CCW : GL_CW);
    if (d_.polygon_offset.factor != 0.0f || d_.polygon_offset.units != 0.0f) {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(d_.polygon_offset.factor, d_.polygon_offset.units);
    } else {
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    if (d_.depth_clamp)
      glEnable(GL_DEPTH_CLAMP);
    else
      glDisable(GL_DEPTH_CLAMP);
  }

  const Context::DepthDraw& d_;
  Program program_;
  Texture depth_;
  Framebuffer fbo_;
  VertexArray vao_;
  Buffer positions_, indices_;
};
}  // namespace

std::vector<uint32_t> Context::render_depth(const DepthDraw& draw) {
  make_current();
  DepthPass pass(draw);
  pass.frame();
  check_gl("the depth draw");
  return read_depth(draw.format, draw.width, draw.height);
}

std::vector<double> Context::time_depth(const DepthDraw& draw, int repeat) {
  make_current();
  DepthPass pass(draw);
  return time_frames(3, repeat, [&] { pass.frame(); });
}

std::vector<double> Context::time_depth_clear(const DepthDraw& draw, int repeat) {
  make_current();
  DepthPass pass(draw);
  return time_frames(3, repeat, [&] { pass.clear(); });
}

std::vector<uint32_t> Context::roundtrip_depth(raster::DepthFormat format, int width, int height,
                                               std::span<const uint32_t> texels) {
  make_current();
  Texture tex;
  glBindTexture(GL_TEXTURE_2D, tex.get());
  define_depth_texture(format, width, height, texels);
  Framebuffer fbo;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex.get(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  check_framebuffer("the depth round trip");
  return read_depth(format, width, height);
}

}  // namespace glref
