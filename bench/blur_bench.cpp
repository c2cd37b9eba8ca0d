// Filterable-map benchmark of issue 19: the separable box blur of a 2048² two-channel (VSM, RG32F) moment map,
// both passes (and of the four- and one-channel maps of EVSM4 and ESM), beside the encode pass (depth →
// moments), the map pass itself (2·10^4 triangles of ~2,000 pixels into a 2048² d32f target, the depth
// benchmark's case b), a plain one-thread copy of the two-channel map (the memory's floor for one pass) and the
// blurred two-channel map's mip chain (moment_mips), at the same thread count in one run. Prints Google
// Benchmark's table (min / median / max; --benchmark_format=json for machine-readable output) and a summary with
// the blur's cost per core (median × threads).
//   shadowlab_bench_blur [--threads N] [--smoke] [--radius R] [benchmark flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench/bench_common.h"
#include "bench/triangle_soup.h"
#include "raster/renderer.h"
#include "shading/techniques/blur_pass.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace bench {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr int kMapSize = 2048;

template <class Fn>
void register_timed(const std::string& name, const bench::Options& opt, Fn fn) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [fn](benchmark::State& st) mutable {
    fn();  // warm-up: pages touched, scratch grown
    for (auto _ : st) {
      const auto t0 = std::chrono::steady_clock::now();
      fn();
      st.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  });
  bench::configure(b, opt);
}

}  // namespace

// The program for this instruction set: bench/isa_main.cpp picks one when it starts.
int run(int argc, char** argv) {
  int radius = 2;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--radius") == 0) {
      radius = std::atoi(argv[i + 1]);
      for (int j = i; j + 2 < argc; ++j) argv[j] = argv[j + 2];
      argc -= 2;
      break;
    }
  bench::Options opt = bench::parse_options(argc, argv);
  const int size = opt.smoke ? 256 : kMapSize;
  raster::Renderer renderer(opt.threads);

  // The map pass and its depth, then moments from it: a realistic map to blur.
  const bench::Soup soup = bench::make_soup(opt.smoke ? 2000 : 20000, 2000.0, size, 2);
  raster::DepthTarget depth(size, size, raster::DepthFormat::d32f);
  auto map_pass = [&] {
    depth.clear(1.0f);
    renderer.draw(raster::RenderTargets{&depth}, raster::DrawState{}, raster::ClipSpaceDepthShader{},
                  std::span<const glm::vec4>(soup.positions), soup.indices);
  };
  map_pass();
  // The targets as the techniques make them (moment_format): VSM two channels (RG32F), EVSM4 four (RGBA32F),
  // ESM one (R32F).
  using shading::tech::MomentKind;
  auto target = [&](MomentKind k) { return raster::ColorTarget(size, size, shading::tech::moment_format(k)); };
  raster::ColorTarget map = target(MomentKind::vsm), scratch = target(MomentKind::vsm);
  raster::ColorTarget map4 = target(MomentKind::evsm4), scratch4 = target(MomentKind::evsm4);
  raster::ColorTarget map1 = target(MomentKind::esm), scratch1 = target(MomentKind::esm);
  shading::tech::MomentParams vsm, evsm4, esm;
  vsm.kind = MomentKind::vsm, evsm4.kind = MomentKind::evsm4, esm.kind = MomentKind::esm;
  const shading::tech::LightDepth linear;
  auto encode = [&] { shading::tech::encode_moments(renderer, depth, linear, vsm, map); };
  encode();
  shading::tech::encode_moments(renderer, depth, linear, evsm4, map4);
  shading::tech::encode_moments(renderer, depth, linear, esm, map1);
  // The floor the memory sets: one thread copying the two-channel map (read 32 MiB, write 32 MiB), what each
  // blur pass must at least move.
  const size_t map_bytes = size_t(map.pitch()) * size_t(map.padded_height()) * 8;

  register_timed("map_pass", opt, map_pass);
  register_timed("encode_vsm", opt, encode);
  register_timed("blur_2ch", opt, [&] { shading::tech::blur_map(renderer, map, scratch, radius); });
  register_timed("blur_h_2ch", opt, [&] { shading::tech::blur_pass(renderer, map, scratch, radius, false); });
  register_timed("blur_4ch", opt, [&] { shading::tech::blur_map(renderer, map4, scratch4, radius); });
  register_timed("blur_1ch", opt, [&] { shading::tech::blur_map(renderer, map1, scratch1, radius); });
  register_timed("copy_2ch", opt, [&] { std::memcpy(scratch.row32f(0), map.row32f(0), map_bytes); });
  // The blurred map's mip chain (moment_mips, on by default): levels 1.. box-filtered from the view's level 0.
  register_timed("mips_2ch", opt, [&] { shading::Texture2D::view(map).generate_mips(); });

  bench::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!reporter.any_ran()) return 0;  // only listed, or nothing matched the filter

  const int threads = std::max(1, renderer.threads());
  const double blur = reporter.median_ms("blur_2ch");
  std::printf("\nFilterable map, %dx%d, box radius %d (%d taps per pass), %d thread(s), medians:\n", size, size, radius,
              2 * radius + 1, renderer.threads());
  std::printf("%-28s %10s\n", "pass", "ms");
  std::printf("%-28s %10.2f\n", "map pass (depth, case b)", reporter.median_ms("map_pass"));
  std::printf("%-28s %10.2f\n", "encode (depth -> z, z^2)", reporter.median_ms("encode_vsm"));
  std::printf("%-28s %10.2f\n", "blur, 2 channels, h + v", blur);
  std::printf("%-28s %10.2f\n", "blur, 2 channels, h only", reporter.median_ms("blur_h_2ch"));
  std::printf("%-28s %10.2f\n", "blur, 4 channels, h + v", reporter.median_ms("blur_4ch"));
  std::printf("%-28s %10.2f\n", "blur, 1 channel, h + v", reporter.median_ms("blur_1ch"));
  std::printf("%-28s %10.2f\n", "copy 2-ch map, 1 thread", reporter.median_ms("copy_2ch"));
  std::printf("%-28s %10.2f\n", "mip chain, 2 channels", reporter.median_ms("mips_2ch"));
  std::printf("blur cost per core (median x threads): %.2f ms (issue 19 asks for at most 2 ms)\n", blur * threads);
  return 0;
}

SHADOWLAB_ISA_END
}  // namespace bench
