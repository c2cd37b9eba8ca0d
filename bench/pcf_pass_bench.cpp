// Shading benchmark of issue 3: a 1920×1080 full-screen pass doing one hardware-PCF lookup per pixel into a
// 2048² d32f map, and one doing 16 Poisson taps (each a PCF lookup), in ms per frame, shadowlab beside llvmpipe
// running the same GLSL (raster/reference: pixel (x, y) reads p = ((x+0.5)/W, (y+0.5)/H) with
// ref = (p.s + p.t)/2, the taps at p + disk[i] · 2 texels, averaged; output grey). A third pass with no lookup (grey = ref) shows what
// the pipeline itself costs each renderer: rasterizing, shading 2×2 quads and writing RGBA8.
// --scaling runs the whole program at 1, 2, 4, … threads, --runs N runs it N times over and lists every run
// (bench_common.h).
//   shadowlab_bench_pcf [--threads N] [--smoke] [--no-llvmpipe] [--repetitions R] [--scaling [LIST]]
//                       [--runs N] [--json-dir DIR] [benchmark flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench/bench_common.h"
#include "raster/reference/gl_reference.h"
#include "raster/renderer.h"
#include "shading/shadow_lookup.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace bench {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr int kMap = 2048;

// The pass's fragment shader, the GLSL of raster/reference written as a C++ shader over one PCF kernel type.
template <class Kernel, int kTaps>
struct PcfPassShader {
  using Vertex = glm::vec4;
  using Varyings = raster::NoVaryings;
  Kernel kernel;
  glm::vec2 inv_target;
  std::array<glm::vec2, 16> offset;  // disk[i] · radius: the product of two uniforms, made once per draw
  PcfPassShader(const Kernel& k, glm::vec2 inv_target, glm::vec2 radius, const std::array<glm::vec2, 16>& disk)
      : kernel(k), inv_target(inv_target) {
    for (int i = 0; i < 16; ++i) offset[i] = disk[i] * radius;
  }
  glm::vec4 vertex(const Vertex& v, Varyings&) const { return v; }
  void fragment(const raster::QuadIn<Varyings>& q, raster::QuadOut& out) const {
    for (int l = 0; l < 4; ++l) {
      const glm::vec2 p = glm::vec2(q.frag_coord[l]) * inv_target;
      const float ref = 0.5f * (p.x + p.y);
      float lit;
      if constexpr (kTaps == 0) {
        lit = ref;
      } else if constexpr (kTaps == 1) {
        lit = kernel(glm::vec3(p, ref));
      } else {
        lit = 0.0f;
        for (int i = 0; i < kTaps; ++i) lit += kernel(glm::vec3(p + offset[i], ref));
        lit *= 1.0f / kTaps;
      }
      out.color[l] = glm::vec4(lit, lit, lit, 1.0f);
    }
  }
  // The same, two quads at a time in SIMD lanes (what the pipeline runs; fragment() stays as the reference).
  void fragment_pair(const raster::QuadPairIn<Varyings>& q, raster::QuadPairOut& out) const {
    using raster::simd::VecF32;
    const VecF32 px = q.frag_x * VecF32::splat(inv_target.x), py = q.frag_y * VecF32::splat(inv_target.y);
    const VecF32 ref = VecF32::splat(0.5f) * (px + py);
    VecF32 lit;
    if constexpr (kTaps == 0) {
      lit = ref;
    } else if constexpr (kTaps == 1) {
      lit = kernel(px, py, ref);
    } else {
      lit = VecF32::splat(0.0f);
      const Kernel k = kernel;  // a local copy: its constants stay in registers across the taps
      if constexpr (shading::detail::kTapsPerLookup == 2) {
        // Two taps per sixteen-lane lookup (one AVX-512 register), kLookupsPerBatch such lookups per call, summed
        // in tap order (as shading/techniques/shadow_filters_x8.h's for_each_tap does).
        using raster::simd::VecF32x16;
        constexpr int kBatch = shading::detail::kLookupsPerBatch;
        static_assert(kTaps % (2 * kBatch) == 0);
        for (int i = 0; i < kTaps; i += 2 * kBatch) {
          std::array<VecF32x16, kBatch> s, t, r2, r;
          for (int j = 0; j < kBatch; ++j) {
            const glm::vec2 o0 = offset[i + 2 * j], o1 = offset[i + 2 * j + 1];
            s[j] = VecF32x16::rows(px + VecF32::splat(o0.x), px + VecF32::splat(o1.x));
            t[j] = VecF32x16::rows(py + VecF32::splat(o0.y), py + VecF32::splat(o1.y));
            r2[j] = VecF32x16::rows(ref, ref);
          }
          k(s, t, r2, r);
          for (const VecF32x16& v : r) lit = lit + v.row0(), lit = lit + v.row1();
        }
      } else {
        for (int i = 0; i < kTaps; ++i)
          lit = lit + k(px + VecF32::splat(offset[i].x), py + VecF32::splat(offset[i].y), ref);
      }
      lit = lit * VecF32::splat(1.0f / kTaps);
    }
    out.color = {lit, lit, lit, VecF32::splat(1.0f)};
  }
};

}  // namespace

// The program for this instruction set: bench/isa_main.cpp picks one when it starts.
int run(int argc, char** argv) {
  if (const auto status = bench::run_scaling(argc, argv)) return *status;
  bench::Options opt = bench::parse_options(argc, argv);
  const int W = opt.smoke ? 480 : 1920, H = opt.smoke ? 270 : 1080;

  // The same random 2048² d32f map for both renderers.
  raster::DepthTarget map(kMap, kMap, raster::DepthFormat::d32f);
  std::vector<uint32_t> texels(size_t(kMap) * kMap);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int y = 0; y < kMap; ++y)
    for (int x = 0; x < kMap; ++x) {
      const float z = u(rng);
      map.row<float>(y)[x] = z;
      texels[size_t(y) * kMap + x] = std::bit_cast<uint32_t>(z);
    }

  raster::Renderer renderer(opt.threads);
  raster::ColorTarget color(W, H, raster::ColorFormat::rgba8);
  const std::vector<glm::vec4> tri = {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}};  // one full-screen triangle
  const shading::Texture2D tex = shading::Texture2D::view(map);
  using Kernel = shading::PcfKernel<shading::TexelFormat::d32f, false>;
  const Kernel kernel{tex.level(0), 0.0f};
  std::array<glm::vec2, 16> disk;
  for (int i = 0; i < 16; ++i) disk[i] = {glref::poisson_disk16()[2 * i], glref::poisson_disk16()[2 * i + 1]};

  std::unique_ptr<glref::Context> gl;
  if (opt.llvmpipe) {
    std::string why;
    gl = glref::Context::create(opt.threads, &why);
    if (!gl) std::fprintf(stderr, "llvmpipe unavailable (%s): shadowlab only\n", why.c_str());
  }
  glref::Context::ShadowSampleQuery q;
  q.tex_width = q.tex_height = kMap;
  q.format = raster::DepthFormat::d32f;
  q.texels = texels;

  auto add_case = [&]<int kTaps>(const std::string& name) {
    const PcfPassShader<Kernel, kTaps> shader(kernel, glm::vec2(1.0f / W, 1.0f / H), glm::vec2(2.0f / kMap), disk);
    auto* b = benchmark::RegisterBenchmark((name + "/shadowlab").c_str(), [&, shader](benchmark::State& st) {
      renderer.draw(raster::RenderTargets{nullptr, &color}, raster::DrawState{}, shader, std::span<const glm::vec4>(tri));
      for (auto _ : st) {
        const auto t0 = std::chrono::steady_clock::now();
        renderer.draw(raster::RenderTargets{nullptr, &color}, raster::DrawState{}, shader, std::span<const glm::vec4>(tri));
        st.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      bench::record_draw_timings(st, renderer.last_timings());  // one iteration per repetition
    });
    bench::configure(b, opt);
    if (gl) {
      auto* g = benchmark::RegisterBenchmark((name + "/llvmpipe").c_str(), [&](benchmark::State& st) {
        const auto ms = gl->time_pcf_pass(W, H, q, kTaps, int(st.max_iterations));
        size_t i = 0;
        for (auto _ : st) st.SetIterationTime(ms[i++ % ms.size()] * 1e-3);
      });
      bench::configure(g, opt);
    }
  };
  add_case.operator()<0>("no_lookup");
  add_case.operator()<1>("pcf_1_tap");
  add_case.operator()<16>("poisson_16_taps");

  bench::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!reporter.any_ran()) return 0;  // only listed, or nothing matched the filter
  std::printf("\nFull-screen PCF pass, %dx%d into a %d² d32f map, %d thread(s), SIMD path %s, medians:\n", W, H, kMap,
              renderer.threads(), SHADOWLAB_ISA_NAME);
  std::printf("%-16s %12s %12s %8s\n", "case", "shadowlab ms", "llvmpipe ms", "ratio");
  for (const char* c : {"no_lookup", "pcf_1_tap", "poisson_16_taps"}) {
    const double sl = reporter.median_ms(std::string(c) + "/shadowlab");
    const double lp = reporter.median_ms(std::string(c) + "/llvmpipe");
    if (sl == 0 && lp == 0) continue;  // filtered out
    std::printf("%-16s %12.2f %12.2f %7.2fx\n", c, sl, lp, sl > 0 && lp > 0 ? lp / sl : 0.0);
  }
  for (const char* c : {"no_lookup", "pcf_1_tap", "poisson_16_taps"}) bench::print_scaling_row(c, renderer.threads(), reporter);
  return 0;
}

SHADOWLAB_ISA_END
}  // namespace bench
