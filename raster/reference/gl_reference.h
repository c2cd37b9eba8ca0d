// The real-GL reference (raster/reference/, target shadowlab::glref): Mesa llvmpipe driven through EGL on the
// surfaceless platform (no window, desktop GL 4.5 core), used by conformance tests to get what GL renders and
// samples from the same inputs, and by benchmarks to time llvmpipe on the same work. It takes raster's formats
// and draw state; only tests/ and bench/ link it, and nothing in raster, shading or scenes depends on GL.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/formats.h"
#include "raster/state.h"

namespace glref {

// Texture wrap modes of GL. `clamp` is the legacy GL_CLAMP, which only a compatibility-profile context accepts.
enum class Wrap : uint8_t { clamp_to_edge, clamp_to_border, repeat, mirrored_repeat, clamp };

enum class Profile : uint8_t { core, compatibility };

class Context {
 public:
  // Makes an llvmpipe context with `threads` rasterizer threads (LP_NUM_THREADS; 0 rasterizes on the calling
  // thread). Forces software rendering through the process environment (LIBGL_ALWAYS_SOFTWARE=1,
  // GALLIUM_DRIVER=llvmpipe, LP_NUM_THREADS=threads) before EGL initialises, because llvmpipe reads them when
  // its screen is created. Returns nullptr and fills *why when EGL, the surfaceless platform, a GL 4.5 context
  // or llvmpipe is unavailable. Throws std::runtime_error if another Context is alive in this process: EGL has
  // one surfaceless display per process, and its llvmpipe screen (with its thread count) is shared.
  static std::unique_ptr<Context> create(int threads, std::string* why, Profile profile = Profile::core);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version() const;   // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  int threads() const { return threads_; }
  Profile profile() const { return profile_; }

  // One depth-only draw of triangles given in clip space (the vertex shader is gl_Position = a_pos; there is no
  // colour attachment). Depth buffer: a depth texture of the format (d16: GL_DEPTH_COMPONENT16, d24:
  // GL_DEPTH_COMPONENT24, d32f: GL_DEPTH_COMPONENT32F) attached to a framebuffer object.
  struct DepthDraw {
    int width = 0, height = 0;
    raster::DepthFormat format = raster::DepthFormat::d32f;
    std::optional<raster::Rect> viewport, scissor;  // default: the whole target, no scissor test
    raster::CullMode cull = raster::CullMode::none;
    raster::FrontFace front_face = raster::FrontFace::ccw;
    raster::DepthFunc depth_func = raster::DepthFunc::less;
    bool depth_write = true;
    raster::PolygonOffset polygon_offset{};  // GL_POLYGON_OFFSET_FILL is enabled when either term is non-zero
    bool depth_clamp = false;
    float clear_depth = 1.0f;
    std::span<const glm::vec4> clip_positions;
    std::span<const uint32_t> indices;  // empty: non-indexed, one triangle per three positions
  };
  // The depth buffer after the draw, one value per pixel, row 0 = bottom row (GL order), encoded like
  // raster::DepthTarget::raw(): the exact unorm code for d16/d24, the float's bit pattern for d32f.
  std::vector<uint32_t> render_depth(const DepthDraw& draw);
  // Benchmark: uploads once, runs 3 warm-up frames, then `repeat` frames of clear + draw + glFinish, each timed
  // separately. Returns milliseconds per frame (clear included: a frame is what a shadow-map pass costs).
  std::vector<double> time_depth(const DepthDraw& draw, int repeat);
  // Milliseconds per depth clear + glFinish alone on the same target (to subtract from time_depth if wanted).
  std::vector<double> time_depth_clear(const DepthDraw& draw, int repeat);
  // Self-check of the encodings: uploads `texels` into a depth texture the way sample_shadow does and reads
  // it back the way render_depth does. Equal to `texels` when both directions are exact.
  std::vector<uint32_t> roundtrip_depth(raster::DepthFormat format, int width, int height,
                                        std::span<const uint32_t> texels);

  // A depth texture read by a shadow sampler: texture(sampler2DShadow, vec3(s, t, ref)) in a fragment shader.
  struct ShadowSampleQuery {
    int tex_width = 0, tex_height = 0;
    raster::DepthFormat format = raster::DepthFormat::d32f;
    std::span<const uint32_t> texels;  // encoded as render_depth returns them, row 0 = t = 0
    bool linear = true;                // GL_LINEAR (hardware PCF) or GL_NEAREST, min and mag alike, one level
    Wrap wrap_s = Wrap::clamp_to_edge, wrap_t = Wrap::clamp_to_edge;
    float border = 0.0f;  // the border colour's red channel: the depth a border texel holds
    raster::DepthFunc compare = raster::DepthFunc::lequal;  // GL_TEXTURE_COMPARE_FUNC: passes when ref OP texel
    std::span<const glm::vec3> coords;  // (s, t, ref) per lookup; unused by time_pcf_pass
  };
  // One result per coordinate, in [0, 1], read back from an R32F target without conversion.
  std::vector<float> sample_shadow(const ShadowSampleQuery& query);
  // Benchmark: a full-screen pass over a width × height RGBA8 target. Pixel (x, y) looks up the shadow map at
  // p = ((x + 0.5)/width, (y + 0.5)/height) with ref = 0.5·(p.s + p.t), a plane across the map.
  // taps == 1: one hardware-PCF lookup at p. taps in 2..16: the first `taps` points of poisson_disk16(),
  // scaled by 2 texels, added to p, each a hardware-PCF lookup, averaged. Output: the shadow factor as grey.
  // Returns milliseconds per frame (draw + glFinish) after 3 warm-up frames.
  std::vector<double> time_pcf_pass(int width, int height, const ShadowSampleQuery& tex, int taps, int repeat);

 private:
  struct Impl;
  Context(std::unique_ptr<Impl> impl, int threads, Profile profile);
  void make_current() const;
  std::unique_ptr<Impl> impl_;
  int threads_;
  Profile profile_;
};

// The 16-point Poisson disk time_pcf_pass uses, as x0, y0, x1, y1, ...: points in the unit disk, pairwise at
// least 0.41 apart (best-candidate dart throwing with a fixed seed, so every prefix is spread out too).
// Exposed so that a shadowlab benchmark can use the very same taps.
std::span<const float, 32> poisson_disk16();

}  // namespace glref
