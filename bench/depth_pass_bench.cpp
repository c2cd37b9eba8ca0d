// Depth-only pass benchmark of issue 2: (a) 10^6 random triangles of ~10 pixels, (b) 2·10^4 of ~2,000 pixels,
// (c) the Stanford dragon fitted to the map, into a 2048² d32f target, with shadowlab and with Mesa llvmpipe on the
// same triangles and the same thread count, in one run. Prints Google Benchmark's table (min / median / max per
// case; --benchmark_format=json for machine-readable output) and then a ratio table.
// With --verify it first renders every case once with both and reports, per case, the pixels whose stored depth
// differs (covered by one only, or any bit of the value) and a hash of shadowlab's map, then exits.
// Each shadowlab repetition also reports where its draw's time went (counters front_ms, back_ms, clear_cpu_ms,
// front_busy_ms, back_busy_ms, chunks in the JSON output: Renderer::last_timings). --scaling runs the whole program
// at 1, 2, 4, … threads, --runs N runs it N times over and lists every run (bench_common.h).
//   shadowlab_bench_depth [--threads N] [--smoke] [--no-llvmpipe] [--verify] [--repetitions R]
//                         [--scaling [LIST]] [--runs N] [--json-dir DIR] [benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_common.h"
#include "bench/triangle_soup.h"
#include "raster/reference/gl_reference.h"
#include "raster/renderer.h"
#include "raster/simd/isa.h"

namespace bench {
SHADOWLAB_ISA_BEGIN

namespace {

struct Workload {
  std::string name;
  bench::Soup soup;
  double pixels = 0;  // sum of the triangles' window-space areas inside the map
};

constexpr int kMapSize = 2048;

std::vector<Workload> make_workloads(bool smoke) {
  std::vector<Workload> w;
  const size_t small = smoke ? 20000 : 1000000, large = smoke ? 2000 : 20000;
  w.push_back({"a_small_10px", bench::make_soup(small, 10.0, kMapSize, 1)});
  w.push_back({"b_large_2000px", bench::make_soup(large, 2000.0, kMapSize, 2)});
  const auto dragon = bench::assets_dir() / "stanford_dragon" / "dragon_vrip.glb";
  if (std::filesystem::exists(dragon)) {
    w.push_back({"c_dragon_871k", bench::fit_mesh_to_map(dragon, kMapSize)});
  } else {
    std::fprintf(stderr, "dragon case skipped: ../shared/assets not found\n");
  }
  for (auto& x : w) x.pixels = bench::window_area(x.soup, kMapSize);
  return w;
}

// FNV-1a over the stored values, rows bottom first: a fingerprint to compare builds with.
uint64_t map_hash(const raster::DepthTarget& t) {
  uint64_t h = 1469598103934665603ull;
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x) h = (h ^ t.raw(x, y)) * 1099511628211ull;
  return h;
}

// --verify: one draw of each case by both renderers, compared pixel by pixel. Returns the process exit code.
int verify(const std::vector<Workload>& workloads, raster::Renderer& renderer, raster::DepthTarget& target,
           glref::Context* gl) {
  int status = 0;
  std::printf("SIMD path %s, %d thread(s)\n", SHADOWLAB_ISA_NAME, renderer.threads());
  for (const Workload& w : workloads) {
    target.clear(1.0f);
    renderer.draw(raster::RenderTargets{&target}, raster::DrawState{}, raster::ClipSpaceDepthShader{},
                  std::span<const glm::vec4>(w.soup.positions), w.soup.indices);
    const unsigned long long hash = map_hash(target);
    if (!gl) {
      std::printf("%-16s hash %016llx (no llvmpipe to compare with)\n", w.name.c_str(), hash);
      continue;
    }
    glref::Context::DepthDraw d;
    d.width = d.height = kMapSize;
    d.format = raster::DepthFormat::d32f;
    d.clip_positions = w.soup.positions;
    d.indices = w.soup.indices;
    const std::vector<uint32_t> ref = gl->render_depth(d);
    const uint32_t clear = std::bit_cast<uint32_t>(1.0f);  // what both maps were cleared to
    size_t coverage = 0, bits = 0;
    for (int y = 0; y < kMapSize; ++y)
      for (int x = 0; x < kMapSize; ++x) {
        const uint32_t a = target.raw(x, y), b = ref[size_t(y) * kMapSize + size_t(x)];
        if ((a == clear) != (b == clear)) ++coverage;
        else if (a != b) ++bits;
      }
    std::printf("%-16s hash %016llx, pixels covered by one only: %zu, other depth differences: %zu\n",
                w.name.c_str(), hash, coverage, bits);
    if (coverage || bits) status = 1;
  }
  return status;
}

}  // namespace

// The program for this instruction set: bench/isa_main.cpp picks one when it starts.
int run(int argc, char** argv) {
  if (const auto status = bench::run_scaling(argc, argv)) return *status;
  bool verify_only = false;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--verify") == 0) {
      verify_only = true;
      for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
      --argc;
      break;
    }
  bench::Options opt = bench::parse_options(argc, argv);
  const auto workloads = make_workloads(opt.smoke);
  raster::Renderer renderer(opt.threads);
  raster::DepthTarget target(kMapSize, kMapSize, raster::DepthFormat::d32f);
  std::unique_ptr<glref::Context> gl;
  if (opt.llvmpipe) {
    std::string why;
    gl = glref::Context::create(opt.threads, &why);
    if (!gl) std::fprintf(stderr, "llvmpipe unavailable (%s): shadowlab only\n", why.c_str());
  }
  if (verify_only) return verify(workloads, renderer, target, gl.get());

  for (const Workload& w : workloads) {
    const double tris = double(w.soup.indices.size() / 3);
    auto counters = [&](benchmark::State& st) {
      st.counters["Mtris/s"] = benchmark::Counter(tris * 1e-6 * double(st.iterations()), benchmark::Counter::kIsRate);
      st.counters["Gpix/s"] = benchmark::Counter(w.pixels * 1e-9 * double(st.iterations()), benchmark::Counter::kIsRate);
    };
    auto draw = [&] {
      target.clear(1.0f);
      renderer.draw(raster::RenderTargets{&target}, raster::DrawState{}, raster::ClipSpaceDepthShader{},
                    std::span<const glm::vec4>(w.soup.positions), w.soup.indices);
    };
    bool warm = false;
    auto* b = benchmark::RegisterBenchmark((w.name + "/shadowlab").c_str(), [&, counters, draw, warm](benchmark::State& st) mutable {
      if (!warm) draw(), warm = true;  // first run: scratch buffers grow, pages are touched
      for (auto _ : st) {
        const auto t0 = std::chrono::steady_clock::now();
        draw();
        st.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      counters(st);
      bench::record_draw_timings(st, renderer.last_timings());  // one iteration per repetition
    });
    bench::configure(b, opt);
    if (gl) {
      // llvmpipe: time_depth warms up, then times one frame per repetition of this benchmark.
      auto* g = benchmark::RegisterBenchmark((w.name + "/llvmpipe").c_str(), [&, counters](benchmark::State& st) {
        glref::Context::DepthDraw d;
        d.width = d.height = kMapSize;
        d.format = raster::DepthFormat::d32f;
        d.clip_positions = w.soup.positions;
        d.indices = w.soup.indices;
        const auto ms = gl->time_depth(d, int(st.max_iterations));
        size_t i = 0;
        for (auto _ : st) st.SetIterationTime(ms[i++ % ms.size()] * 1e-3);
        counters(st);
      });
      bench::configure(g, opt);
    }
  }
  bench::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!reporter.any_ran()) return 0;  // only listed, or nothing matched the filter

  std::printf("\nDepth-only pass, %dx%d d32f, %d thread(s), SIMD path %s, medians:\n", kMapSize, kMapSize,
              renderer.threads(), SHADOWLAB_ISA_NAME);
  std::printf("%-16s %12s %12s %10s %10s %10s %10s %8s\n", "case", "shadowlab ms", "llvmpipe ms", "SL Mtri/s",
              "LP Mtri/s", "SL Gpix/s", "LP Gpix/s", "ratio");
  for (const Workload& w : workloads) {
    const double tris = double(w.soup.indices.size() / 3);
    const double sl = reporter.median_ms(w.name + "/shadowlab");
    const double lp = reporter.median_ms(w.name + "/llvmpipe");
    if (sl == 0 && lp == 0) continue;  // filtered out
    auto rate = [](double n, double ms) { return ms > 0 ? n / (ms * 1e3) : 0.0; };
    std::printf("%-16s %12.2f %12.2f %10.2f %10.2f %10.3f %10.3f %7.2fx\n", w.name.c_str(), sl, lp, rate(tris, sl),
                rate(tris, lp), rate(w.pixels, sl) * 1e-3, rate(w.pixels, lp) * 1e-3, sl > 0 && lp > 0 ? lp / sl : 0.0);
  }
  std::printf("\nshadowlab's draw, medians: front end / back end ms (wall), and the time spent in each phase's "
              "tasks and in the clear (summed over workers)\n");
  for (const Workload& w : workloads) {
    const std::string n = w.name + "/shadowlab";
    if (reporter.median_ms(n) == 0) continue;  // filtered out
    auto m = [&](const char* counter) { return reporter.median_counter(n, counter); };
    std::printf("%-16s %8.2f / %8.2f, busy %8.2f / %8.2f, clear %6.2f, %g chunks\n", w.name.c_str(), m("front_ms"),
                m("back_ms"), m("front_busy_ms"), m("back_busy_ms"), m("clear_cpu_ms"), m("chunks"));
    bench::print_scaling_row(w.name, renderer.threads(), reporter);
  }
  return 0;
}

SHADOWLAB_ISA_END
}  // namespace bench
