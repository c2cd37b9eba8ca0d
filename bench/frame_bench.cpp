// Frame benchmark of issue 5: the built-in `tutorial` frame at 1920×1080 with a 2048² shadow map, for the
// filters hard, pcf, poisson (16 taps) and early-bail, in ms per frame (map pass and camera pass together).
//   shadowlab_bench_frame [--threads N] [--smoke] [benchmark flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "bench/bench_common.h"
#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "raster/simd/isa.h"

namespace bench {
SHADOWLAB_ISA_BEGIN

// The program for this instruction set: bench/isa_main.cpp picks one when it starts.
int run(int argc, char** argv) {
  bench::Options opt = bench::parse_options(argc, argv);
  const scenes::Scene scene = scenes::builtin_scene("tutorial");
  raster::Renderer renderer(opt.threads);
  const char* filters[] = {"hard", "pcf", "poisson", "early-bail"};
  for (const char* filter : filters) {
    frame::FrameConfig o;
    o.width = opt.smoke ? 480 : 1920;
    o.height = opt.smoke ? 270 : 1080;
    o.map_size = opt.smoke ? 512 : 2048;
    o.filter = *shading::tech::parse_filter(filter);
    if (std::string(filter) == "poisson") o.poisson_taps = 16;
    auto* b = benchmark::RegisterBenchmark((std::string("tutorial/") + filter).c_str(), [&, o](benchmark::State& st) {
      frame::render_frame(scene, o, renderer);  // warm-up
      for (auto _ : st) {
        const auto t0 = std::chrono::steady_clock::now();
        const frame::Frame f = frame::render_frame(scene, o, renderer);
        st.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        st.counters["shadow_ms"] = f.stats.shadow_ms;
        st.counters["camera_ms"] = f.stats.camera_ms;
      }
    });
    bench::configure(b, opt);
  }
  bench::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!reporter.any_ran()) return 0;  // only listed, or nothing matched the filter
  std::printf("\ntutorial frame %s, %d thread(s), medians:\n", opt.smoke ? "480x270, 512² map" : "1920x1080, 2048² d16 map",
              renderer.threads());
  for (const char* filter : filters)
    std::printf("%-12s %8.2f ms\n", filter, reporter.median_ms(std::string("tutorial/") + filter));
  return 0;
}

SHADOWLAB_ISA_END
}  // namespace bench
