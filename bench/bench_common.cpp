// Options, repetitions and workload helpers shared by the benchmark programs (see bench_common.h).
#include "bench/bench_common.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <sys/wait.h>

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

// The first processor's "model name", "cpu family" and "model" lines of /proc/cpuinfo, and the logical CPUs, as
// one line ("AMD EPYC (family 25, model 17), 2 logical CPUs"); what the system does not say is left out.
std::string cpu_line() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, name, family, model;
  auto value = [](const std::string& l) {
    const size_t c = l.find(':');
    std::string v = c == std::string::npos ? "" : l.substr(c + 1);
    v.erase(0, v.find_first_not_of(" \t"));
    return v;
  };
  while (std::getline(in, line) && !line.empty()) {
    if (line.rfind("model name", 0) == 0) name = value(line);
    else if (line.rfind("cpu family", 0) == 0) family = value(line);
    else if (line.rfind("model", 0) == 0 && line.find("name") == std::string::npos) model = value(line);
  }
  std::string out = name.empty() ? "unknown CPU" : name;
  if (!family.empty()) out += " (family " + family + (model.empty() ? "" : ", model " + model) + ")";
  return out + ", " + std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " logical CPUs";
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// "a–b" with two decimals, or one value where both read the same; "—" for none.
std::string range_text(const std::vector<double>& v) {
  if (v.empty()) return "—";
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  char a[32], b[32];
  std::snprintf(a, sizeof a, "%.2f", *lo);
  std::snprintf(b, sizeof b, "%.2f", *hi);
  return std::strcmp(a, b) == 0 ? std::string(a) : std::string(a) + "–" + b;
}

// A JSON string literal.
std::string json_string(const std::string& v) {
  std::string out = "\"";
  for (const char c : v) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

}  // namespace

std::optional<int> run_scaling(int argc, char** argv) {
  bool scaling = false, runs_given = false;
  int runs = 1;
  int threads = -1;
  std::vector<int> counts;
  std::string json_dir;
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scaling" || a.rfind("--scaling=", 0) == 0) {
      scaling = true;
      std::string list_text;
      if (a != "--scaling") list_text = a.substr(10);
      else if (i + 1 < argc && std::isdigit(static_cast<unsigned char>(argv[i + 1][0]))) list_text = argv[++i];
      std::stringstream list(list_text);
      for (std::string n; std::getline(list, n, ',');) counts.push_back(std::max(0, std::atoi(n.c_str())));
    } else if (a == "--runs" || a.rfind("--runs=", 0) == 0) {
      const std::string v = a != "--runs" ? a.substr(7) : i + 1 < argc ? argv[++i] : "";
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n < 1 || n > 1000) {
        std::fprintf(stderr, "--runs: expected a whole number of runs from 1 to 1000, got '%s'\n", v.c_str());
        return 2;
      }
      runs = int(n), runs_given = true;
    } else if (a == "--json-dir" || a.rfind("--json-dir=", 0) == 0) {
      json_dir = a != "--json-dir" ? a.substr(11) : i + 1 < argc ? argv[++i] : "";
      if (json_dir.empty()) {
        std::fprintf(stderr, "--json-dir: expected a directory\n");
        return 2;
      }
    } else if (a == "--threads" && i + 1 < argc) {
      threads = std::atoi(argv[++i]);  // each run gets its own (--scaling), or this one (--runs)
    } else {
      rest.push_back(a);
    }
  }
  if (!scaling && !runs_given) return std::nullopt;
  if (!scaling) {
    counts = {threads};  // -1: the program's default (the hardware's threads)
  } else if (counts.empty()) {
    const int hw = std::max(1, int(std::thread::hardware_concurrency()));
    for (int n = 1; n < hw; n *= 2) counts.push_back(n);
    counts.push_back(hw);
  }
  const std::string program = std::filesystem::path(argv[0]).filename().string();
  if (!json_dir.empty()) {  // made here, once: else every run would fail on its own --benchmark_out
    std::error_code ec;
    std::filesystem::create_directories(json_dir, ec);
    if (ec || !std::filesystem::is_directory(json_dir)) {
      std::fprintf(stderr, "--json-dir: cannot make the directory '%s' (%s)\n", json_dir.c_str(),
                   ec ? ec.message().c_str() : "a file of that name is in the way");
      return 2;
    }
  }
  struct Row {
    std::string name;
    int threads, run;
    double sl, lp, front, back, clear, front_busy, back_busy;
  };
  std::vector<Row> rows;
  std::vector<std::string> failed;  // "run R, N thread(s): exit X", one per process that did not end well
  std::string simd_path;
  // Run by run, every thread count in each, so that a slow phase of the machine touches all counts alike.
  for (int run = 1; run <= runs; ++run) {
    for (int n : counts) {
      std::string cmd = shell_quote(std::filesystem::read_symlink("/proc/self/exe").string());
      if (n >= 0) cmd += " --threads " + std::to_string(n);
      for (const std::string& a : rest) {
        cmd += ' ';
        cmd += shell_quote(a);
      }
      std::string tag;
      if (n >= 0) tag += "_t" + std::to_string(n);
      if (runs_given) tag += "_run" + std::to_string(run);
      if (!json_dir.empty())
        cmd += " --benchmark_out=" + shell_quote(json_dir + "/" + program + tag + ".json") +
               " --benchmark_out_format=json";
      const std::string count = n >= 0 ? std::to_string(n) + " thread(s)" : "default threads";
      const std::string what = (runs_given ? "run " + std::to_string(run) + ", " : std::string()) + count;
      std::printf("==== %s, %s", program.c_str(), count.c_str());
      if (runs_given) std::printf(", run %d of %d", run, runs);
      std::printf("\n");
      std::fflush(stdout);
      FILE* p = popen(cmd.c_str(), "r");
      if (!p) {
        failed.push_back(what + ": could not be started (" + std::strerror(errno) + ")");
        continue;
      }
      char line[4096];
      while (std::fgets(line, sizeof line, p)) {
        std::fputs(line, stdout);
        if (std::strncmp(line, "@row ", 5) == 0) {
          char name[256];
          Row r{};
          if (std::sscanf(line + 5, "%255s %d %lf %lf %lf %lf %lf %lf %lf", name, &r.threads, &r.sl, &r.lp,
                          &r.front, &r.back, &r.clear, &r.front_busy, &r.back_busy) == 9) {
            r.name = name;
            r.run = run;
            rows.push_back(r);
          }
        } else if (const char* sp = std::strstr(line, "SIMD path "); sp && simd_path.empty()) {
          char isa[32];
          if (std::sscanf(sp + 10, "%31[a-z0-9]", isa) == 1) simd_path = isa;
        }
      }
      std::fflush(stdout);
      const int st = pclose(p);
      if (st != 0)
        failed.push_back(what + ": " + (WIFEXITED(st) ? "exit " + std::to_string(WEXITSTATUS(st))
                                                       : "ended by signal " + std::to_string(WTERMSIG(st))));
    }
  }
  std::vector<std::string> names;
  std::vector<int> measured;  // thread counts, in the order asked for (those that reported rows)
  for (const Row& r : rows)
    if (std::find(names.begin(), names.end(), r.name) == names.end()) names.push_back(r.name);
  for (int n : counts)
    for (const Row& r : rows)
      if ((n < 0 || r.threads == n) && std::find(measured.begin(), measured.end(), r.threads) == measured.end())
        measured.push_back(r.threads);
  auto rows_of = [&](const std::string& name, int t) {
    std::vector<const Row*> out;
    for (const Row& r : rows)
      if (r.name == name && r.threads == t) out.push_back(&r);
    return out;
  };
  // One row per case and count: each field the median over the runs (the run's own value with one run).
  auto merged = [&](const std::string& name, int t) {
    Row m{name, t, 0, 0, 0, 0, 0, 0, 0, 0};
    const auto rs = rows_of(name, t);
    auto med = [&](double Row::*f) {
      std::vector<double> v;
      for (const Row* r : rs) v.push_back(r->*f);
      return median_of(v);
    };
    m.sl = med(&Row::sl), m.lp = med(&Row::lp), m.front = med(&Row::front), m.back = med(&Row::back);
    m.clear = med(&Row::clear), m.front_busy = med(&Row::front_busy), m.back_busy = med(&Row::back_busy);
    return m;
  };
  std::ostringstream json;
  json << "{\n  \"program\": " << json_string(program) << ",\n  \"cpu\": " << json_string(cpu_line())
       << ",\n  \"simd_path\": " << json_string(simd_path) << ",\n  \"runs\": " << runs << ",\n  \"failed\": [";
  for (size_t i = 0; i < failed.size(); ++i) json << (i ? ", " : "") << json_string(failed[i]);
  json << "],\n  \"rows\": [";
  bool first = true;
  if (scaling) {
    // Speed-up against each renderer's own time at the smallest count measured (1 thread unless LIST says
    // otherwise).
    std::printf("\nScaling, %s (speed-up and efficiency against each renderer's time at %d thread(s)%s):\n",
                program.c_str(), measured.empty() ? counts.front() : measured.front(),
                runs > 1 ? "; every time the median over the runs, the ratio that of those medians" : "");
    // "use": a phase's task time summed over workers / (threads × its wall time): how busy its workers were.
    std::printf("%-18s %7s %11s %11s %7s %8s %6s %8s %6s %9s %9s %9s %9s %9s\n", "case", "threads", "shadowlab",
                "llvmpipe", "ratio", "SL x", "SL eff", "LP x", "LP eff", "front ms", "front use", "back ms",
                "back use", "clear cpu");
    for (const std::string& name : names) {
      std::optional<Row> base;
      for (int t : measured) {
        if (rows_of(name, t).empty()) continue;
        const Row r = merged(name, t);
        if (!base) base = r;
        const double tt = std::max(r.threads, 1) / double(std::max(base->threads, 1));
        const double sx = r.sl > 0 ? base->sl / r.sl : 0, lx = r.lp > 0 ? base->lp / r.lp : 0;
        const int workers = std::max(r.threads, 1);
        const double front_use = r.front > 0 ? r.front_busy / (workers * r.front) : 0;
        const double back_use = r.back > 0 ? r.back_busy / (workers * r.back) : 0;
        std::printf("%-18s %7d %9.2fms %9.2fms %6.2fx %7.2fx %6.2f %7.2fx %6.2f %9.2f %9.2f %9.2f %9.2f %9.2f\n",
                    name.c_str(), r.threads, r.sl, r.lp, r.sl > 0 && r.lp > 0 ? r.lp / r.sl : 0.0, sx, sx / tt, lx,
                    lx / tt, r.front, front_use, r.back, back_use, r.clear);
        json << (first ? "" : ",") << "\n    {\"case\": " << json_string(name) << ", \"threads\": " << r.threads
             << ", \"shadowlab_ms\": " << r.sl << ", \"llvmpipe_ms\": " << r.lp
             << ", \"ratio\": " << (r.sl > 0 ? r.lp / r.sl : 0) << ", \"shadowlab_speedup\": " << sx
             << ", \"shadowlab_efficiency\": " << sx / tt << ", \"llvmpipe_speedup\": " << lx
             << ", \"llvmpipe_efficiency\": " << lx / tt << ", \"front_ms\": " << r.front
             << ", \"back_ms\": " << r.back << ", \"clear_cpu_ms\": " << r.clear
             << ", \"front_busy_ms\": " << r.front_busy << ", \"back_busy_ms\": " << r.back_busy
             << ", \"front_use\": " << front_use << ", \"back_use\": " << back_use << "}";
        first = false;
      }
    }
  }
  json << "\n  ],\n  \"each_run\": [";
  first = true;
  for (const Row& r : rows) {
    json << (first ? "" : ",") << "\n    {\"case\": " << json_string(r.name) << ", \"threads\": " << r.threads
         << ", \"run\": " << r.run << ", \"shadowlab_ms\": " << r.sl << ", \"llvmpipe_ms\": " << r.lp
         << ", \"ratio\": " << (r.sl > 0 && r.lp > 0 ? r.lp / r.sl : 0) << ", \"front_ms\": " << r.front
         << ", \"back_ms\": " << r.back << "}";
    first = false;
  }
  json << "\n  ],\n  \"summary\": [";
  first = true;
  if (runs_given) {
    // Every run listed, as the README's tables quote them: each run's ratio of the two medians, their median,
    // and the range of each renderer's per-run medians; Markdown, to paste as it is.
    bool any_llvmpipe = false;
    for (const Row& r : rows) any_llvmpipe |= r.lp > 0;
    std::printf("\n%d run(s) of %s, %s, SIMD path %s (each run: the ratio of llvmpipe's median time to "
                "shadowlab's in that process%s):\n\n",
                runs, program.c_str(), cpu_line().c_str(), simd_path.empty() ? "?" : simd_path.c_str(),
                any_llvmpipe ? "" : "; llvmpipe did not run, so there are no ratios");
    std::printf("| case | threads | runs (ratio) | median | shadowlab ms | llvmpipe ms | front end / back end ms |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const std::string& name : names)
      for (int t : measured) {
        const auto rs = rows_of(name, t);
        if (rs.empty()) continue;
        std::string each;
        std::vector<double> ratio, sl, lp, front, back;
        for (const Row* r : rs) {
          char buf[32] = "—";
          if (r->sl > 0 && r->lp > 0) {
            std::snprintf(buf, sizeof buf, "%.2f", r->lp / r->sl);
            ratio.push_back(r->lp / r->sl);
          }
          each += (each.empty() ? "" : " / ") + std::string(buf);
          if (r->sl > 0) sl.push_back(r->sl), front.push_back(r->front), back.push_back(r->back);
          if (r->lp > 0) lp.push_back(r->lp);
        }
        char med[32] = "—";
        if (!ratio.empty()) std::snprintf(med, sizeof med, "**%.2f×**", median_of(ratio));
        const bool timed = !back.empty() && *std::max_element(back.begin(), back.end()) > 0;
        const std::string split = timed ? range_text(front) + " / " + range_text(back) : "—";
        std::printf("| %s | %d | %s%s | %s | %s | %s | %s |\n", name.c_str(), t, each.c_str(),
                    ratio.empty() ? "" : "×", med, range_text(sl).c_str(), range_text(lp).c_str(), split.c_str());
        json << (first ? "" : ",") << "\n    {\"case\": " << json_string(name) << ", \"threads\": " << t
             << ", \"runs\": " << rs.size() << ", \"ratios\": [";
        for (size_t i = 0; i < ratio.size(); ++i) json << (i ? ", " : "") << ratio[i];
        json << "], \"median_ratio\": " << median_of(ratio);
        auto min_max = [&](const char* key, const std::vector<double>& v) {
          if (v.empty()) return;
          const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
          json << ", \"" << key << "_min\": " << *lo << ", \"" << key << "_max\": " << *hi;
        };
        min_max("shadowlab_ms", sl), min_max("llvmpipe_ms", lp);
        json << "}";
        first = false;
      }
    if (!failed.empty()) std::printf("\n");
    for (const std::string& f : failed) std::printf("Failed: %s (its rows are missing above)\n", f.c_str());
  }
  json << "\n  ]\n}\n";
  if (!json_dir.empty()) {
    const std::string path = json_dir + "/" + program + (scaling ? "_scaling.json" : "_runs.json");
    std::ofstream out(path);
    out << json.str();
    if (!out.flush()) {
      std::fprintf(stderr, "%s: cannot write the collected rows to %s\n", program.c_str(), path.c_str());
      return 1;
    }
  }
  return failed.empty() ? 0 : 1;
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
