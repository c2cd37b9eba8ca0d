// Options, repetitions and workload helpers shared by the benchmark programs (see bench_common.h).
#include "bench/bench_common.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
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
  // Both renderers get the same explicit count: "the hardware's" is resolved here (llvmpipe takes no -1).
  if (o.threads < 0) o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
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
        (r.run_type == Run::RT_Iteration && !median_ms_.count(name))) {
      median_ms_[name] = r.GetAdjustedRealTime();
      for (const auto& [k, c] : r.counters) counters_[name][k] = c.value;
    }
  }
  ConsoleReporter::ReportRuns(runs);
}

double MedianReporter::median_ms(const std::string& name) const {
  const auto it = median_ms_.find(name);
  return it == median_ms_.end() ? 0.0 : it->second;
}

double MedianReporter::median_counter(const std::string& name, const std::string& counter) const {
  const auto it = counters_.find(name);
  if (it == counters_.end()) return 0.0;
  const auto c = it->second.find(counter);
  return c == it->second.end() ? 0.0 : c->second;
}

void print_scaling_row(const std::string& case_name, int threads, const MedianReporter& reporter) {
  const std::string n = case_name + "/shadowlab";
  if (reporter.median_ms(n) == 0 && reporter.median_ms(case_name + "/llvmpipe") == 0) return;  // filtered out
  auto counter = [&](const char* c) { return reporter.median_counter(n, c); };
  std::printf("@row %s %d %.4f %.4f %.4f %.4f %.4f %.4f %.4f\n", case_name.c_str(), threads, reporter.median_ms(n),
              reporter.median_ms(case_name + "/llvmpipe"), counter("front_ms"), counter("back_ms"),
              counter("clear_cpu_ms"), counter("front_busy_ms"), counter("back_busy_ms"));
}

namespace {
std::string shell_quote(const std::string& a) {
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

std::optional<int> run_scaling(int argc, char** argv) {
  bool scaling = false;
  std::vector<int> counts;
  std::string json_dir;
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scaling") {
      scaling = true;
      if (i + 1 < argc && std::isdigit(static_cast<unsigned char>(argv[i + 1][0]))) {
        std::stringstream list(argv[++i]);
        for (std::string n; std::getline(list, n, ',');) counts.push_back(std::max(0, std::atoi(n.c_str())));
      }
    } else if (a == "--json-dir" && i + 1 < argc) {
      json_dir = argv[++i];
    } else if (a == "--threads" && i + 1 < argc) {
      ++i;  // each run gets its own
    } else {
      rest.push_back(a);
    }
  }
  if (!scaling) return std::nullopt;
  if (counts.empty()) {
    const int hw = std::max(1, int(std::thread::hardware_concurrency()));
    for (int n = 1; n < hw; n *= 2) counts.push_back(n);
    counts.push_back(hw);
  }
  const std::string program = std::filesystem::path(argv[0]).filename().string();
  struct Row {
    std::string name;
    int threads;
    double sl, lp, front, back, clear, front_busy, back_busy;
  };
  std::vector<Row> rows;
  int status = 0;
  for (int n : counts) {
    std::string cmd = shell_quote(std::filesystem::read_symlink("/proc/self/exe").string()) + " --threads " +
                      std::to_string(n);
    for (const std::string& a : rest) cmd += " " + shell_quote(a);
    if (!json_dir.empty())
      cmd += " --benchmark_out=" + shell_quote(json_dir + "/" + program + "_t" + std::to_string(n) + ".json") +
             " --benchmark_out_format=json";
    std::printf("==== %s, %d thread(s)\n", program.c_str(), n);
    std::fflush(stdout);
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return 1;
    char line[4096];
    while (std::fgets(line, sizeof line, p)) {
      std::fputs(line, stdout);
      if (std::strncmp(line, "@row ", 5) == 0) {
        char name[256];
        Row r{};
        if (std::sscanf(line + 5, "%255s %d %lf %lf %lf %lf %lf %lf %lf", name, &r.threads, &r.sl, &r.lp, &r.front,
                        &r.back, &r.clear, &r.front_busy, &r.back_busy) == 9) {
          r.name = name;
          rows.push_back(r);
        }
      }
    }
    std::fflush(stdout);
    if (pclose(p) != 0) status = 1;
  }
  // Speed-up against each renderer's own time at the smallest count measured (1 thread unless LIST says otherwise).
  std::vector<std::string> names;
  for (const Row& r : rows)
    if (std::find(names.begin(), names.end(), r.name) == names.end()) names.push_back(r.name);
  std::printf("\nScaling, %s (speed-up and efficiency against each renderer's time at %d thread(s)):\n",
              program.c_str(), counts.front());
  // "use": a phase's task time summed over workers / (threads × its wall time): how busy its workers were.
  std::printf("%-18s %7s %11s %11s %7s %8s %6s %8s %6s %9s %9s %9s %9s %9s\n", "case", "threads", "shadowlab",
              "llvmpipe", "ratio", "SL x", "SL eff", "LP x", "LP eff", "front ms", "front use", "back ms", "back use",
              "clear cpu");
  std::ostringstream json;
  json << "{\n  \"program\": \"" << program << "\",\n  \"rows\": [";
  bool first = true;
  for (const std::string& name : names) {
    const Row* base = nullptr;
    for (const Row& r : rows)
      if (r.name == name && !base) base = &r;
    for (const Row& r : rows) {
      if (r.name != name) continue;
      const double t = std::max(r.threads, 1) / double(std::max(base->threads, 1));
      const double sx = r.sl > 0 ? base->sl / r.sl : 0, lx = r.lp > 0 ? base->lp / r.lp : 0;
      const int workers = std::max(r.threads, 1);
      const double front_use = r.front > 0 ? r.front_busy / (workers * r.front) : 0;
      const double back_use = r.back > 0 ? r.back_busy / (workers * r.back) : 0;
      std::printf("%-18s %7d %9.2fms %9.2fms %6.2fx %7.2fx %6.2f %7.2fx %6.2f %9.2f %9.2f %9.2f %9.2f %9.2f\n",
                  name.c_str(), r.threads, r.sl, r.lp, r.sl > 0 && r.lp > 0 ? r.lp / r.sl : 0.0, sx, sx / t, lx,
                  lx / t, r.front, front_use, r.back, back_use, r.clear);
      json << (first ? "" : ",") << "\n    {\"case\": \"" << name << "\", \"threads\": " << r.threads
           << ", \"shadowlab_ms\": " << r.sl << ", \"llvmpipe_ms\": " << r.lp
           << ", \"ratio\": " << (r.sl > 0 ? r.lp / r.sl : 0) << ", \"shadowlab_speedup\": " << sx
           << ", \"shadowlab_efficiency\": " << sx / t << ", \"llvmpipe_speedup\": " << lx
           << ", \"llvmpipe_efficiency\": " << lx / t << ", \"front_ms\": " << r.front
           << ", \"back_ms\": " << r.back << ", \"clear_cpu_ms\": " << r.clear
           << ", \"front_busy_ms\": " << r.front_busy << ", \"back_busy_ms\": " << r.back_busy
           << ", \"front_use\": " << front_use << ", \"back_use\": " << back_use << "}";
      first = false;
    }
  }
  json << "\n  ]\n}\n";
  if (!json_dir.empty()) std::ofstream(json_dir + "/" + program + "_scaling.json") << json.str();
  return status;
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
