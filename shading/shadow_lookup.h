// A shadow map lookup resolved once per draw. ShadowLookup2D snapshots a Texture2D and its compare sampler and
// picks a path: the common shadow case (d16, d24 or d32f, compare LEQUAL, LINEAR without mips, clamp_to_edge
// or clamp_to_border on both axes) runs a kernel specialised at compile time for that format and wrap
// (pcf_kernel.h, pcf_kernel16.h); every other sampler takes the generic lookups of lookup.h. Both give identical
// results (same arithmetic in the same order); the bulk form is what conformance tests and benchmarks call.
//
//   // once per draw: a view of the depth pass's target (no copy) and a PCF sampler
//   shading::ShadowLookup2D shadow(shading::Texture2D::view(depth_target), shading::Sampler::pcf());
//   // in the shader's fragment(), per lane: light_clip = bias · light view-projection · world position
//   const float lit = shadow.proj(q.in[l].light_clip);  // textureProj(sampler2DShadow, …)
//   // or, to compile the shader once per path: shadow.visit([&](auto kernel) { draw(MyShader{kernel}); });
#pragma once
#include <array>
#include <span>
#include <stdexcept>

#include "shading/lookup.h"
#include "shading/pcf_kernel16.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// A lookup specialised at compile time: one fast path (format and wrap fixed), ...
template <TexelFormat F, bool kBorderWrap>
struct PcfKernel {
  TextureLevel level;
  float border_depth;
  detail::Pcf16Level wide;  // the level's constants for the SIMD forms, splatted once

  PcfKernel(const TextureLevel& level, float border_depth) : level(level), border_depth(border_depth), wide(level) {}
  float operator()(glm::vec3 str) const { return detail::pcf_lequal<F, kBorderWrap>(level, str, border_depth); }
  // Eight lookups in SIMD lanes (for fragment_pair shaders), each equal to the one-lookup form.
  raster::simd::VecF32 operator()(raster::simd::VecF32 s, raster::simd::VecF32 t, raster::simd::VecF32 ref) const {
    return detail::pcf_lequal_x8<F, kBorderWrap>(wide.half, s, t, ref, border_depth);
  }
  // Sixteen (two taps of a fragment_pair's eight points, say), each equal to the one-lookup form: one 512-bit
  // kernel in AVX-512 builds.
  raster::simd::VecF32x16 operator()(raster::simd::VecF32x16 s, raster::simd::VecF32x16 t,
                                     raster::simd::VecF32x16 ref) const {
    return detail::pcf_lequal_x16<F, kBorderWrap>(wide, s, t, ref, border_depth);
  }
  // N sixteen-lane lookups at once (a multi-tap filter's taps, detail::kLookupsPerBatch of them), each equal to
  // the form above: AVX-512 builds run them side by side (detail::pcf_lequal_gather16_n).
  template <size_t N>
  void operator()(const std::array<raster::simd::VecF32x16, N>& s, const std::array<raster::simd::VecF32x16, N>& t,
                  const std::array<raster::simd::VecF32x16, N>& ref,
                  std::array<raster::simd::VecF32x16, N>& out) const {
    detail::pcf_lequal_x16_n<F, kBorderWrap>(wide, s, t, ref, out, border_depth);
  }
};
// ... or the generic lookups for any other sampler, with a shorter scalar path for the NEAREST shadow case
// (detail::nearest_compare: one texel read and compared; the tutorial's hard shadows and Poisson taps). Measured
// with border_texel inlined (filter.h) on the 2-core AMD EPYC (Zen 5, AVX-512 build, shadowlab_bench_frame
// --threads 2, the tutorial frame at 1920×1080, three runs each, alternating with the build before): Poisson
// 279–313 → 128–134 ms, early-bail 131 → 88–91 ms, hard 84–89 → 75–80 ms.
class GenericShadowKernel {
 public:
  // The texture (which must outlive the kernel and keep its levels) and sampler are fixed for the kernel's life:
  // what the NEAREST path needs of them is read here, once.
  GenericShadowKernel(const Texture2D* texture, const Sampler& sampler)
      : texture_(texture), sampler_(sampler), nearest_(detail::nearest_fast_path_applies(*texture, sampler)),
        level0_(texture->level(0)), border_(border_red(texture_->format(), sampler.border_color)) {}
  const Texture2D& texture() const { return *texture_; }
  const Sampler& sampler() const { return sampler_; }
  // Whether lookups take detail::nearest_compare (exposed for tests).
  bool nearest_fast() const { return nearest_; }

  float operator()(glm::vec3 str) const {
    if (nearest_)
      return detail::visit_depth_format(texture_->format(), [&](auto f) {
        return detail::nearest_compare<decltype(f)::value>(level0_, sampler_.wrap_s, sampler_.compare_func, border_,
                                                           str);
      });
    return shading::texture_at(*texture_, sampler_, str, 0.0f);
  }
  raster::simd::VecF32 operator()(raster::simd::VecF32 s, raster::simd::VecF32 t, raster::simd::VecF32 ref) const {
    alignas(32) float ps[8], pt[8], pr[8], out[8];
    s.store(ps), t.store(pt), ref.store(pr);
    if (nearest_) {  // the format chosen once for the eight lanes
      detail::visit_depth_format(texture_->format(), [&](auto f) {
        for (int l = 0; l < 8; ++l)
          out[l] = detail::nearest_compare<decltype(f)::value>(level0_, sampler_.wrap_s, sampler_.compare_func, border_,
                                                               glm::vec3(ps[l], pt[l], pr[l]));
        return 0;
      });
    } else {
      for (int l = 0; l < 8; ++l) out[l] = shading::texture_at(*texture_, sampler_, glm::vec3(ps[l], pt[l], pr[l]), 0.0f);
    }
    return raster::simd::VecF32::load(out);
  }
  raster::simd::VecF32x16 operator()(raster::simd::VecF32x16 s, raster::simd::VecF32x16 t,
                                     raster::simd::VecF32x16 ref) const {
    return raster::simd::VecF32x16::rows((*this)(s.row0(), t.row0(), ref.row0()), (*this)(s.row1(), t.row1(), ref.row1()));
  }
  template <size_t N>
  void operator()(const std::array<raster::simd::VecF32x16, N>& s, const std::array<raster::simd::VecF32x16, N>& t,
                  const std::array<raster::simd::VecF32x16, N>& ref,
                  std::array<raster::simd::VecF32x16, N>& out) const {
    for (size_t n = 0; n < N; ++n) out[n] = (*this)(s[n], t[n], ref[n]);
  }

 private:
  const Texture2D* texture_;
  Sampler sampler_;
  bool nearest_;
  TextureLevel level0_;
  float border_;
};

class ShadowLookup2D {
 public:
  enum class Path : uint8_t { generic, d16_edge, d16_border, d24_edge, d24_border, d32f_edge, d32f_border };

  ShadowLookup2D() = default;
  // The texture handle is copied (cheap; a view still needs its target alive); so is the sampler.
  ShadowLookup2D(const Texture2D& texture, const Sampler& sampler) : texture_(texture), sampler_(sampler) {
    if (texture.empty()) throw std::invalid_argument("ShadowLookup2D: empty texture");
    level0_ = texture.level(0);
    border_ = border_red(texture.format(), sampler.border_color);
    path_ = choose_path(texture, sampler);
  }

  Path path() const { return path_; }
  bool fast() const { return path_ != Path::generic; }
  const Texture2D& texture() const { return texture_; }
  const Sampler& sampler() const { return sampler_; }

  // texture(sampler2DShadow, str): what shading::texture(texture, sampler, str) returns.
  float operator()(glm::vec3 str) const {
    switch (path_) {
      case Path::generic: break;
      case Path::d16_edge: return detail::pcf_lequal<TexelFormat::d16, false>(level0_, str, border_);
      case Path::d16_border: return detail::pcf_lequal<TexelFormat::d16, true>(level0_, str, border_);
      case Path::d24_edge: return detail::pcf_lequal<TexelFormat::d24, false>(level0_, str, border_);
      case Path::d24_border: return detail::pcf_lequal<TexelFormat::d24, true>(level0_, str, border_);
      case Path::d32f_edge: return detail::pcf_lequal<TexelFormat::d32f, false>(level0_, str, border_);
      case Path::d32f_border: return detail::pcf_lequal<TexelFormat::d32f, true>(level0_, str, border_);
    }
    return shading::texture_at(texture_, sampler_, str, 0.0f);
  }

  // textureProj(sampler2DShadow, strq), with texture_proj's handling of q <= 0.
  float proj(glm::vec4 strq) const {
    if (!projectable(strq.w)) return 0.0f;
    const float w = 1.0f / strq.w;
    return (*this)(glm::vec3(strq.x * w, strq.y * w, strq.z * w));
  }

  // A quad with implicit derivatives: the fast paths have one level and one filter, so λ does not matter.
  Quad<float> operator()(const Quad<glm::vec3>& str, Derivative d = Derivative::coarse) const {
    if (path_ == Path::generic) return shading::texture(texture_, sampler_, str, d);
    return {(*this)(str[0]), (*this)(str[1]), (*this)(str[2]), (*this)(str[3])};
  }

  // Bulk: out[k] = (*this)(str[k]). The path is chosen once for the whole span.
  void operator()(std::span<const glm::vec3> str, std::span<float> out) const {
    if (out.size() < str.size()) throw std::invalid_argument("ShadowLookup2D: output span too short");
    switch (path_) {
      case Path::generic:
        return run(str, out, [&](glm::vec3 p) { return shading::texture_at(texture_, sampler_, p, 0.0f); });
      case Path::d16_edge: return run_fast<TexelFormat::d16, false>(str, out);
      case Path::d16_border: return run_fast<TexelFormat::d16, true>(str, out);
      case Path::d24_edge: return run_fast<TexelFormat::d24, false>(str, out);
      case Path::d24_border: return run_fast<TexelFormat::d24, true>(str, out);
      case Path::d32f_edge: return run_fast<TexelFormat::d32f, false>(str, out);
      case Path::d32f_border: return run_fast<TexelFormat::d32f, true>(str, out);
    }
  }

  // Calls fn(kernel) with the kernel of this lookup's path as its own type (PcfKernel<F, border> or
  // GenericShadowKernel), so a shader templated on it runs with no per-lookup dispatch at all: the run-time
  // choice is made once per draw, here.
  template <class Fn>
  decltype(auto) visit(Fn&& fn) const {
    switch (path_) {
      case Path::generic: break;
      case Path::d16_edge: return fn(PcfKernel<TexelFormat::d16, false>{level0_, border_});
      case Path::d16_border: return fn(PcfKernel<TexelFormat::d16, true>{level0_, border_});
      case Path::d24_edge: return fn(PcfKernel<TexelFormat::d24, false>{level0_, border_});
      case Path::d24_border: return fn(PcfKernel<TexelFormat::d24, true>{level0_, border_});
      case Path::d32f_edge: return fn(PcfKernel<TexelFormat::d32f, false>{level0_, border_});
      case Path::d32f_border: return fn(PcfKernel<TexelFormat::d32f, true>{level0_, border_});
    }
    return fn(GenericShadowKernel{&texture_, sampler_});
  }

  // Which path a texture and sampler get (exposed for tests and benchmarks).
  static Path choose_path(const Texture2D& t, const Sampler& s) {
    if (!detail::pcf_fast_path_applies(t, s)) return Path::generic;
    const bool border = s.wrap_s == Wrap::clamp_to_border;
    switch (t.format()) {
      case TexelFormat::d16: return border ? Path::d16_border : Path::d16_edge;
      case TexelFormat::d24: return border ? Path::d24_border : Path::d24_edge;
      case TexelFormat::d32f: return border ? Path::d32f_border : Path::d32f_edge;
      default: return Path::generic;
    }
  }

 private:
  template <class Fn>
  static void run(std::span<const glm::vec3> str, std::span<float> out, Fn&& fn) {
    for (size_t k = 0; k < str.size(); ++k) out[k] = fn(str[k]);
  }
  template <TexelFormat F, bool kBorderWrap>
  void run_fast(std::span<const glm::vec3> str, std::span<float> out) const {
    detail::pcf_lequal_many<F, kBorderWrap>(level0_, str.data(), out.data(), str.size(), border_);
  }

  Texture2D texture_;
  Sampler sampler_;
  TextureLevel level0_;
  float border_ = 1.0f;
  Path path_ = Path::generic;
};

// Bulk lookups for tests and benchmarks: out[k] = texture(t, s, str[k]) (shadow) or texture(t, s, st[k]).
inline void texture_many(const Texture2D& t, const Sampler& s, std::span<const glm::vec3> str, std::span<float> out) {
  ShadowLookup2D(t, s)(str, out);
}
inline void texture_many(const Texture2D& t, const Sampler& s, std::span<const glm::vec2> st,
                         std::span<glm::vec4> out) {
  if (out.size() < st.size()) throw std::invalid_argument("texture_many: output span too short");
  for (size_t k = 0; k < st.size(); ++k) out[k] = texture(t, s, st[k]);
}

SHADOWLAB_ISA_END
}  // namespace shading
