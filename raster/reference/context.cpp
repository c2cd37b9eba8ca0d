// The reference's EGL side: forcing llvmpipe, opening the surfaceless display, creating and tearing down the
// desktop GL context. Everything EGL holds belongs to the Context object; its destructor terminates the display.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "raster/reference/gl_reference.h"
#include "raster/reference/gl_util.h"

namespace glref {

struct Context::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;

  ~Impl() {
    if (display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    eglTerminate(display);  // releases the llvmpipe screen and its rasterizer threads
    eglReleaseThread();
  }
};

namespace {
std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", unsigned(eglGetError()));
  return std::string(what) + " failed (EGL error " + code + ")";
}

bool has_word(const char* list, std::string_view word) {
  if (!list) return false;
  const std::string_view s(list);
  for (size_t pos = 0; (pos = s.find(word, pos)) != std::string_view::npos; pos += word.size()) {
    const bool starts = pos == 0 || s[pos - 1] == ' ';
    const bool ends = pos + word.size() == s.size() || s[pos + word.size()] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

std::unique_ptr<Context> Context::create(int threads, std::string* why, Profile profile) {
  auto fail = [&](std::string reason) -> std::unique_ptr<Context> {
    if (why) *why = "GL reference unavailable: " + std::move(reason);
    return nullptr;
  };
  if (threads < 0) throw std::invalid_argument("glref: thread count must be >= 0");

  // llvmpipe reads these when EGL creates its screen, i.e. in eglInitialize below.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);
  setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_word(client_ext, "EGL_MESA_platform_surfaceless"))
    return fail("EGL client extension EGL_MESA_platform_surfaceless is missing (is libegl-mesa0 installed?)");
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) return fail("eglGetPlatformDisplayEXT not found");

  auto impl = std::make_unique<Impl>();
  EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) return fail(egl_error("eglGetPlatformDisplayEXT(surfaceless)"));
  // The surfaceless display is one per process. If it is initialised already, another Context owns it, and
  // terminating it here would pull the context from under that one.
  if (eglQueryString(display, EGL_VERSION) != nullptr)
    throw std::runtime_error("glref: another glref::Context (or EGL user) holds the surfaceless display; "
                             "destroy it first (llvmpipe's thread count is fixed per display)");
  eglGetError();  // clear the EGL_NOT_INITIALIZED the probe above recorded
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return fail(egl_error("eglInitialize(surfaceless)"));
  impl->display = display;  // from here the Impl destructor terminates it

  if (!has_word(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
    return fail("EGL_KHR_no_config_context is missing");
  if (!eglBindAPI(EGL_OPENGL_API)) return fail(egl_error("eglBindAPI(EGL_OPENGL_API)"));
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            profile == Profile::core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
                                                     : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                            EGL_NONE};
  impl->context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (impl->context == EGL_NO_CONTEXT) return fail(egl_error("eglCreateContext(desktop GL 4.5)"));
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl->context))
    return fail(egl_error("eglMakeCurrent(surfaceless)"));

  const std::string renderer = gl_string(GL_RENDERER);
  if (renderer.find("llvmpipe") == std::string::npos)
    return fail("GL_RENDERER is \"" + renderer + "\", not llvmpipe");
  return std::unique_ptr<Context>(new Context(std::move(impl), threads, profile));
}

Context::Context(std::unique_ptr<Impl> impl, int threads, Profile profile)
    : impl_(std::move(impl)), threads_(threads), profile_(profile) {}

Context::~Context() = default;

void Context::make_current() const {
  if (eglGetCurrentContext() == impl_->context) return;
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
    throw std::runtime_error("glref: " + egl_error("eglMakeCurrent"));
}

std::string Context::renderer() const {
  make_current();
  return gl_string(GL_RENDERER);
}

std::string Context::version() const {
  make_current();
  return gl_string(GL_VERSION);
}

}  // namespace glref
