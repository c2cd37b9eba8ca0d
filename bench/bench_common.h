// Shared by the benchmark programs: command-line options (threads, smoke mode, llvmpipe on/off), repetitions
// with min / median / max, the asset folder, and workload helpers (a glTF mesh fitted to a square map, the
// window-space area of a soup).
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/triangle_soup.h"

namespace bench {

struct Options {
  int threads = -1;      // -1: the hardware's
  bool smoke = false;    // one repetition, small workloads: for CI
  bool llvmpipe = true;  // also time Mesa llvmpipe
  int repetitions = 7;
};

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

 private:
  std::map<std::string, double> median_ms_;
};

// Loads every triangle of a glTF file (through scenes/) and maps it into clip space with an orthographic
// light looking along −(0.5, 2, 2), fitted to the mesh's bounds, as a directional shadow pass would.
Soup fit_mesh_to_map(const std::filesystem::path& gltf, int map_size);

// Sum of the triangles' window-space areas (pixels) on a size×size viewport, each clipped to it only roughly
// (triangles are assumed inside): the fragment count the pass produces.
double window_area(const Soup& soup, int size);

}  // namespace bench
