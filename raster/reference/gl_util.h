// Internal to the GL reference: owning handles for GL objects, error checks that throw, shader compilation,
// depth-texture upload and readback in the exact encodings of raster::DepthTarget::raw(), and frame timing.
// Every function here expects the reference's context to be current on the calling thread.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "raster/formats.h"
#include "raster/state.h"

namespace glref::detail {

// Throws std::runtime_error("GL error GL_INVALID_OPERATION after <what>") if GL recorded an error.
void check_gl(std::string_view what);
// Throws unless the bound draw framebuffer is complete, naming the status.
void check_framebuffer(std::string_view what);

// An owning GL object name created by Gen and released by Del (the glGen*/glDelete* pairs).
template <void (*Gen)(GLsizei, GLuint*), void (*Del)(GLsizei, const GLuint*)>
class Name {
 public:
  Name() { Gen(1, &id_); }
  ~Name() {
    if (id_) Del(1, &id_);
  }
  Name(Name&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Name& operator=(Name&&) = delete;
  Name(const Name&) = delete;
  GLuint get() const { return id_; }

 private:
  GLuint id_ = 0;
};
inline void gen_textures(GLsizei n, GLuint* ids) { glGenTextures(n, ids); }
inline void delete_textures(GLsizei n, const GLuint* ids) { glDeleteTextures(n, ids); }
using Buffer = Name<&glGenBuffers, &glDeleteBuffers>;
using VertexArray = Name<&glGenVertexArrays, &glDeleteVertexArrays>;
using Framebuffer = Name<&glGenFramebuffers, &glDeleteFramebuffers>;
using Texture = Name<&gen_textures, &delete_textures>;

// A linked program, deleted with the object.
class Program {
 public:
  // Compiles and links; throws with the info log (and `name`) on failure.
  Program(std::string_view name, const std::string& vertex_src, const std::string& fragment_src);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  GLuint get() const { return id_; }
  GLint uniform(const char* name) const;  // throws if the uniform does not exist (or was optimised away)

 private:
  GLuint id_ = 0;
};

GLenum depth_internal_format(raster::DepthFormat f);
GLenum compare_func(raster::DepthFunc f);

// Allocates one level of a depth texture of the format on the bound GL_TEXTURE_2D; if `texels` is not empty
// (width·height values, encoded like DepthTarget::raw(), row 0 at the bottom) uploads them exactly (a d24
// texture with texels is then GL_DEPTH24_STENCIL8, see the .cpp).
void define_depth_texture(raster::DepthFormat f, int width, int height, std::span<const uint32_t> texels);
// Reads the depth attachment of the bound read framebuffer, encoded like DepthTarget::raw(), row 0 at the
// bottom. d16 is read as GL_UNSIGNED_SHORT, d24 as GL_UNSIGNED_INT (code in the top 24 bits), d32f as GL_FLOAT.
std::vector<uint32_t> read_depth(raster::DepthFormat f, int width, int height);

// Runs `frame` warmup times, then `repeat` times with glFinish after each, timing each run on a steady clock.
// Returns milliseconds per run.
std::vector<double> time_frames_impl(int warmup, int repeat, void (*call)(void*), void* arg);

template <class Frame>
std::vector<double> time_frames(int warmup, int repeat, Frame&& frame) {
  return time_frames_impl(
      warmup, repeat, [](void* f) { (*static_cast<std::remove_reference_t<Frame>*>(f))(); }, &frame);
}

}  // namespace glref::detail
