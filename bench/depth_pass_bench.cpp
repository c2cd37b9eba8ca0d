// Depth-only pass benchmark of issue 2: (a) 10^6 random triangles of ~10 pixels, (b) 2·10^4 of ~2,000 pixels,
// (c) the Stanford dragon fitted to the map, into a 2048² d32f target, with shadowlab and with Mesa llvmpipe on the
// same triangles and the same thread count, in one run. Prints Google Benchmark's table (min / median / max per
// case; --benchmark_format=json for machine-readable output) and then a ratio table.
//   shadowlab_bench_depth [--threads N] [--smoke] [--no-llvmpipe] [benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_common.h"
#include "bench/triangle_soup.h"
#include "raster/renderer.h"
#include "tests/gl/gl_reference.h"

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

}  // namespace

int main(int argc, char** argv) {
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

  std::printf("\nDepth-only pass, %dx%d d32f, %d thread(s), medians:\n", kMapSize, kMapSize, renderer.threads());
  std::printf("%-16s %12s %12s %10s %10s %10s %10s %8s\n", "case", "shadowlab ms", "llvmpipe ms", "SL Mtri/s",
              "LP Mtri/s", "SL Gpix/s", "LP Gpix/s", "ratio");
  for (const Workload& w : workloads) {
    const double tris = double(w.soup.indices.size() / 3);
    const double sl = reporter.median_ms(w.name + "/shadowlab");
    const double lp = reporter.median_ms(w.name + "/llvmpipe");
    auto rate = [](double n, double ms) { return ms > 0 ? n / (ms * 1e3) : 0.0; };
    std::printf("%-16s %12.2f %12.2f %10.2f %10.2f %10.3f %10.3f %7.2fx\n", w.name.c_str(), sl, lp, rate(tris, sl),
                rate(tris, lp), rate(w.pixels, sl) * 1e-3, rate(w.pixels, lp) * 1e-3, sl > 0 && lp > 0 ? lp / sl : 0.0);
  }
  return 0;
}
