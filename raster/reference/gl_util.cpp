// GL helpers of the reference: error checks, shader programs, exact depth upload/readback and frame timing.
// Depth codes travel as integers in both directions, never through a float, so no code can be lost.
#include "raster/reference/gl_util.h"

#include <chrono>
#include <stdexcept>

namespace glref::detail {

namespace {
const char* error_name(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

GLuint compile(GLenum stage, std::string_view name, const std::string& src) {
  const GLuint s = glCreateShader(stage);
  const char* text = src.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(s, len, nullptr, log.data());
    glDeleteShader(s);
    throw std::runtime_error("glref: " + std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader of " + std::string(name) + " does not compile: " + log);
  }
  return s;
}
}  // namespace

void check_gl(std::string_view what) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  throw std::runtime_error("glref: " + std::string(error_name(e)) + " after " + std::string(what));
}

void check_framebuffer(std::string_view what) {
  const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  const char* name = status == GL_FRAMEBUFFER_UNSUPPORTED                     ? "GL_FRAMEBUFFER_UNSUPPORTED"
                     : status == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT         ? "incomplete attachment"
                     : status == GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT ? "missing attachment"
                                                                              : "incomplete";
  throw std::runtime_error("glref: framebuffer for " + std::string(what) + " is not complete (" + name + ")");
}

Program::Program(std::string_view name, const std::string& vertex_src, const std::string& fragment_src) {
  const GLuint vs = compile(GL_VERTEX_SHADER, name, vertex_src);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, name, fragment_src);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(id_, len, nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error("glref: program " + std::string(name) + " does not link: " + log);
  }
  check_gl("building program " + std::string(name));
}

Program::~Program() { glDeleteProgram(id_); }

GLint Program::uniform(const char* name) const {
  const GLint loc = glGetUniformLocation(id_, name);
  if (loc < 0) throw std::runtime_error("glref: program has no active uniform " + std::string(name));
  return loc;
}

GLenum depth_internal_format(raster::DepthFormat f) {
  switch (f) {
    case raster::DepthFormat::d16: return GL_DEPTH_COMPONENT16;
    case raster::DepthFormat::d24: return GL_DEPTH_COMPONENT24;
    case raster::DepthFormat::d32f: return GL_DEPTH_COMPONENT32F;
  }
  throw std::runtime_error("glref: unknown depth format");
}

GLenum compare_func(raster::DepthFunc f) {
  switch (f) {
    case raster::DepthFunc::never: return GL_NEVER;
    case raster::DepthFunc::less: return GL_LESS;
    case raster::DepthFunc::equal: return GL_EQUAL;
    case raster::DepthFunc::lequal: return GL_LEQUAL;
    case raster::DepthFunc::greater: return GL_GREATER;
    case raster::DepthFunc::notequal: return GL_NOTEQUAL;
    case raster::DepthFunc::gequal: return GL_GEQUAL;
    case raster::DepthFunc::always: return GL_ALWAYS;
  }
  throw std::runtime_error("glref: unknown depth function");
}

void define_depth_texture(raster::DepthFormat f, int width, int height, std::span<const uint32_t> texels) {
  const size_t n = size_t(width) * size_t(height);
  if (!texels.empty() && texels.size() != n)
    throw std::runtime_error("glref: " + std::to_string(texels.size()) + " depth texels given for a " +
                             std::to_string(width) + "x" + std::to_string(height) + " texture");
  // Mesa stores d24 uploads given as GL_DEPTH_COMPONENT/GL_UNSIGNED_INT through a float and truncates, which
  // loses codes (code k can come back as k - 1). GL_DEPTH_STENCIL/GL_UNSIGNED_INT_24_8 into a depth-stencil
  // texture is stored as given, so uploaded d24 maps use GL_DEPTH24_STENCIL8 (sampled as depth, the default
  // GL_DEPTH_STENCIL_TEXTURE_MODE). d16 (GL_UNSIGNED_SHORT) and d32f (GL_FLOAT) match their storage exactly.
  const bool d24_upload = f == raster::DepthFormat::d24 && !texels.empty();
  glTexStorage2D(GL_TEXTURE_2D, 1, d24_upload ? GL_DEPTH24_STENCIL8 : depth_internal_format(f), width, height);
  check_gl("allocating a depth texture");
  if (texels.empty()) return;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (f == raster::DepthFormat::d16) {
    std::vector<uint16_t> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = uint16_t(texels[i]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, v.data());
  } else if (f == raster::DepthFormat::d24) {
    std::vector<uint32_t> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = texels[i] << 8;  // depth code in the top 24 bits, stencil 0
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, v.data());
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  }
  check_gl("uploading depth texels");
}

std::vector<uint32_t> read_depth(raster::DepthFormat f, int width, int height) {
  const size_t n = size_t(width) * size_t(height);
  std::vector<uint32_t> out(n);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (f == raster::DepthFormat::d16) {
    std::vector<uint16_t> v(n);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, v.data());
    for (size_t i = 0; i < n; ++i) out[i] = v[i];
  } else if (f == raster::DepthFormat::d24) {
    // Mesa expands a 24-bit code z to the 32-bit (z << 8) | (z >> 16) here, so the top 24 bits are z.
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out.data());
    for (uint32_t& x : out) x >>= 8;
  } else {
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, out.data());  // bit patterns, as floats
  }
  check_gl("reading depth");
  return out;
}

std::vector<double> time_frames_impl(int warmup, int repeat, void (*call)(void*), void* arg) {
  for (int i = 0; i < warmup; ++i) {
    call(arg);
    glFinish();
  }
  std::vector<double> ms;
  ms.reserve(size_t(repeat > 0 ? repeat : 0));
  for (int i = 0; i < repeat; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    call(arg);
    glFinish();
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  check_gl("timed frames");
  return ms;
}

}  // namespace glref::detail
