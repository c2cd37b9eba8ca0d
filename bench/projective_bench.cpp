// Projective-shadow benchmark of issue 7: the built-in `projective` scene with 1, 10 and 100 casters (figures),
// static (the same scene every frame: the cache reuses every map) and moving (every figure walks between
// frames: every map is rebuilt), in multipass and single-pass, reporting ms per frame (maps and camera pass)
// and maps rebuilt per frame. Scenes are built before timing; a warm-up frame fills the cache.
//   shadowlab_bench_projective [--threads N] [--smoke] [--repetitions N] [benchmark flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_common.h"
#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "raster/simd/isa.h"

namespace bench {
SHADOWLAB_ISA_BEGIN

namespace {

struct Case {
  int casters;
  bool moving;
  const char* mode;
  std::string name() const {
    return "projective/" + std::to_string(casters) + (moving ? "/moving/" : "/static/") + mode;
  }
};

struct Result {
  double rebuilt = 0, passes = 0;
};

}  // namespace

// The program for this instruction set: bench/isa_main.cpp picks one when it starts.
int run(int argc, char** argv) {
  bench::Options opt = bench::parse_options(argc, argv);
  raster::Renderer renderer(opt.threads);
  const int width = opt.smoke ? 320 : 1280, height = opt.smoke ? 180 : 720;
  const int frames = opt.smoke ? 2 : 8;  // distinct moving frames, cycled
  std::vector<Case> cases;
  for (int n : {1, 10, 100})
    for (bool moving : {false, true})
      for (const char* mode : {"multipass", "single-pass"}) cases.push_back({n, moving, mode});
  std::vector<Result> results(cases.size());

  for (size_t c = 0; c < cases.size(); ++c) {
    const Case k = cases[c];
    auto scenes_for = std::make_shared<std::vector<scenes::Scene>>();
    for (int f = 0; f < (k.moving ? frames : 1); ++f)
      scenes_for->push_back(scenes::builtin_scene("projective", {f / 24.0, k.casters}));
    frame::FrameConfig o;
    o.width = width;
    o.height = height;
    o.params["projective_mode"] = std::string(k.mode);
    o.export_maps = false;
    auto* b = benchmark::RegisterBenchmark(k.name().c_str(), [&, c, o, scenes_for](benchmark::State& st) {
      frame::FrameCache cache;
      size_t next = 0;
      auto scene = [&]() -> const scenes::Scene& { return (*scenes_for)[next++ % scenes_for->size()]; };
      frame::render_frame(scene(), o, renderer, &cache);  // warm-up: fills the cache
      for (auto _ : st) {
        const auto t0 = std::chrono::steady_clock::now();
        const frame::Frame f = frame::render_frame(scene(), o, renderer, &cache);
        st.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        st.counters["maps_rebuilt"] = double(f.stats.projective.maps_rebuilt);
        st.counters["shadow_passes"] = double(f.stats.projective.shadow_passes);
        results[c] = {double(f.stats.projective.maps_rebuilt), double(f.stats.projective.shadow_passes)};
      }
    });
    bench::configure(b, opt);
  }
  bench::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!reporter.any_ran()) return 0;  // only listed, or nothing matched the filter
  std::printf("\nprojective scene %dx%d, 256² maps per caster, %d thread(s), medians:\n", width, height,
              renderer.threads());
  std::printf("%-8s %-8s %-12s %12s %14s %14s\n", "casters", "motion", "mode", "ms/frame", "maps rebuilt", "extra passes");
  for (size_t c = 0; c < cases.size(); ++c)
    std::printf("%-8d %-8s %-12s %12.2f %14.0f %14.0f\n", cases[c].casters, cases[c].moving ? "moving" : "static",
                cases[c].mode, reporter.median_ms(cases[c].name()), results[c].rebuilt, results[c].passes);
  return 0;
}

SHADOWLAB_ISA_END
}  // namespace bench
