// Shared by the benchmark programs: command-line options (threads, smoke mode, llvmpipe on/off), repetitions
// with min / median / max, the asset folder, and workload helpers (a glTF mesh fitted to a square map, the
// window-space area of a soup).
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/triangle_soup.h"

namespace bench {

struct Options {
  int threads = -1;      // -1 (no --threads): the hardware's, resolved by parse_options
  bool smoke = false;    // one repetition, small workloads: for CI
  bool llvmpipe = true;  // also time Mesa llvmpipe
  int repetitions = 7;
};

// --scaling [LIST]: runs this very program once per thread count (LIST such as 1,2,4; by default 1, 2, 4, … up to
// the hardware's threads, and that count itself), each with the other arguments and --threads N, echoes each
// run's output, and ends with a table of every case at every count: shadowlab and llvmpipe medians, their
// ratio, and each renderer's speed-up over its own 1-thread time and parallel efficiency (speed-up / threads).
// --json-dir DIR also writes each run's Google Benchmark JSON (DIR/<program>_t<N>.json) and the table
// (DIR/<program>_scaling.json).
// --runs N (or --runs=N, 1 … 1000): runs the program N times over, each a process of its own (with --scaling,
// every count in each run, run after run), and ends with a Markdown table of every case and count: each run's
// ratio of llvmpipe's median time to shadowlab's, the median of those ratios, the range of each renderer's
// per-run medians and of shadowlab's front end and back end, under a line naming the CPU and the SIMD path, and a
// "Failed:" line for each run that did not exit 0 (the exit code is then 1); with --scaling the scaling table then
// takes each time's median over the runs. --json-dir DIR writes each run's JSON as <program>[_t<N>]_run<R>.json and
// the collected rows (each run's, the table's summary, the failed runs) as DIR/<program>_runs.json (or
// _scaling.json); DIR (also --json-dir=DIR) is made if missing. A bad --runs value, a missing --json-dir value or
// a DIR that cannot be made is one line on stderr and exit code 2. Returns the exit code when --scaling
// or --runs was given, nullopt otherwise.
std::optional<int> run_scaling(int argc, char** argv);
// What a program prints per case for run_scaling to collect: the medians of "<case>/shadowlab" and
// "<case>/llvmpipe" in ms, and of shadowlab's draw split (the counters record_draw_timings sets); nothing for a
// case that did not run (filtered out).
class MedianReporter;
void print_scaling_row(const std::string& case_name, int threads, const MedianReporter& reporter);

// Records a shadowlab repetition's draw split (raster::DrawTimings, Renderer::last_timings) as counters, one
// iteration per repetition: front_ms, back_ms (wall), clear_cpu_ms, front_busy_ms, back_busy_ms (summed over
// workers), chunks.
template <class Timings>
void record_draw_timings(benchmark::State& st, const Timings& dt) {
  st.counters["front_ms"] = dt.front_ms;
  st.counters["back_ms"] = dt.back_ms;
  st.counters["clear_cpu_ms"] = dt.clear_cpu_ms;
  st.counters["front_busy_ms"] = dt.front_busy_ms;
  st.counters["back_busy_ms"] = dt.back_busy_ms;
  st.counters["chunks"] = double(dt.chunks);
}

// Reads and removes shadowlab's own flags from argv, then initialises Google Benchmark with the rest.
Options parse_options(int& argc, char** argv);
// Sets one iteration per repetition, the repetition count, manual timing in milliseconds and min / max
// statistics (Google Benchmark adds mean, median and stddev) on a registered benchmark.
void configure(benchmark::internal::Benchmark* b, const Options& opt);

std::filesystem::path assets_dir();

// Google Benchmark's console table, remembering each benchmark's median real time (or its single run's time
// when there is one repetition) by name, for the ratio tables the programs print at the end.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override;
  // Milliseconds, 0 when the benchmark did not run.
  double median_ms(const std::string& name) const;
  // The median of a user counter (0 when absent).
  double median_counter(const std::string& name, const std::string& counter) const;
  // Whether any benchmark ran: false for --benchmark_list_tests or a filter that matches nothing, when the
  // summary tables after the run have nothing to show.
  bool any_ran() const { return !median_ms_.empty(); }

 private:
  std::map<std::string, double> median_ms_;
  std::map<std::string, std::map<std::string, double>> counters_;
};

// Loads every triangle of a glTF file (through scenes/) and maps it into clip space with an orthographic
// light looking along −(0.5, 2, 2), fitted to the mesh's bounds, as a directional shadow pass would.
Soup fit_mesh_to_map(const std::filesystem::path& gltf, int map_size);

// Sum of the triangles' window-space areas (pixels) on a size×size viewport, each clipped to it only roughly
// (triangles are assumed inside): the fragment count the pass produces.
double window_area(const Soup& soup, int size);

}  // namespace bench
