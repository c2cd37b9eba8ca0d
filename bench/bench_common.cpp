// Options, repetitions and workload helpers shared by the benchmark programs (see bench_common.h).
#include "bench/bench_common.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf_import.h"
#include "scenes/scene_queries.h"

namespace bench {

Options parse_options(int& argc, char** argv) {
  Options o;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc) {
      o.threads = std::atoi(argv[++i]);
    } else if (a == "--smoke") {
      o.smoke = true;
      o.repetitions = 1;
    } else if (a == "--no-llvmpipe") {
      o.llvmpipe = false;
    } else if (a == "--repetitions" && i + 1 < argc) {
      o.repetitions = std::max(1, std::atoi(argv[++i]));
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  benchmark::Initialize(&argc, argv);
  return o;
}

void configure(benchmark::internal::Benchmark* b, const Options& opt) {
  b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(opt.repetitions);
  b->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
  b->ComputeStatistics("max", [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); });
}

void MedianReporter::ReportRuns(const std::vector<Run>& runs) {
  for (const Run& r : runs) {
    const std::string& name = r.run_name.function_name;
    if ((r.run_type == Run::RT_Aggregate && r.aggregate_name == "median") ||
        (r.run_type == Run::RT_Iteration && !median_ms_.count(name)))
      median_ms_[name] = r.GetAdjustedRealTime();
  }
  ConsoleReporter::ReportRuns(runs);
}

double MedianReporter::median_ms(const std::string& name) const {
  const auto it = median_ms_.find(name);
  return it == median_ms_.end() ? 0.0 : it->second;
}

std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("SHADOWLAB_ASSETS")) return env;
  return std::filesystem::path(SHADOWLAB_SOURCE_DIR) / ".." / "shared" / "assets";
}

Soup fit_mesh_to_map(const std::filesystem::path& gltf, int) {
  const scenes::Scene scene = scenes::import_gltf(gltf);
  const scenes::TriangleSoup flat = scenes::flatten(scene);
  const glm::vec3 to_light = glm::normalize(glm::vec3(0.5f, 2.0f, 2.0f));
  const glm::mat4 view = glm::lookAt(to_light, glm::vec3(0.0f), glm::abs(to_light.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : flat.positions) {
    const glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
    lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  const glm::mat4 proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);
  Soup s;
  s.positions.reserve(flat.positions.size());
  for (const glm::vec3& p : flat.positions) s.positions.push_back(proj * view * glm::vec4(p, 1.0f));
  s.indices = flat.indices;
  return s;
}

double window_area(const Soup& soup, int size) {
  double sum = 0;
  for (size_t i = 0; i + 2 < soup.indices.size(); i += 3) {
    glm::dvec2 p[3];
    for (int k = 0; k < 3; ++k) {
      const glm::vec4 c = soup.positions[soup.indices[i + k]];
      p[k] = glm::dvec2((c.x / c.w + 1) * 0.5 * size, (c.y / c.w + 1) * 0.5 * size);
    }
    sum += std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y)) * 0.5;
  }
  return sum;
}

}  // namespace bench
