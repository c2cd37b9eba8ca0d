// raster/simd/isa.h's rule, checked over the sources: every namespace block a file of the per-instruction-set
// libraries opens at file scope opens SHADOWLAB_ISA_BEGIN next and closes SHADOWLAB_ISA_END, so nothing of theirs
// is one symbol shared by the AVX2 and the scalar build. A block left outside compiles and links, and where it is
// an inline function that calls into the pipeline, the linker may hand the scalar path its AVX2 copy: only this
// check notices. The plain-data headers the scene library shares are the listed exceptions. And a namespace that
// one file opens inside a set's namespace (`namespace raster { SHADOWLAB_ISA_BEGIN namespace detail {`) must not
// be opened at file scope by another (`namespace raster::detail {`): C++ extends the inner one from there, so
// the second file's declarations land one set's namespace deeper and no longer match the first's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kIsaFolders = {"raster", "raster/simd", "shading", "shading/techniques",
                                              "scenes/io", "scenes/frame", "scenes/reference", "cli", "bench"};
// Built once and shared (their types cross between the sets and the scene library), or the entry points that
// choose the set and the choice itself (built for plain x86-64), and the benchmarks' plain helpers.
const std::set<std::string> kShared = {"raster/formats.h", "raster/state.h", "raster/simd/isa.h",
                                       "raster/simd/isa_select.h", "raster/simd/isa_select.cpp", "raster/simd/isa_entry.h",
                                       "shading/tone_map.h", "shading/techniques/vocabulary.h", "cli/main.cpp",
                                       "bench/isa_main.cpp", "bench/bench_common.h", "bench/bench_common.cpp",
                                       "bench/triangle_soup.h"};
// Namespaces of other libraries a file may reopen (CLI11's, for a forward declaration).
const std::set<std::string> kForeign = {"CLI"};

struct Finding {
  std::string file;
  int line;
  std::string what;
};

struct Scan {
  std::vector<Finding> findings;
  std::vector<std::pair<std::string, int>> file_scope;  // blocks opened at file scope, with their lines
  std::set<std::string> nested;  // blocks opened inside a file-scope block, qualified by it ("raster::detail")
};

// Walks the file's namespace blocks at file scope: `namespace X {` with its matching `}  // namespace X`, the
// repository's form (blocks nested inside them are inside the set's namespace already).
Scan scan_file(const fs::path& path, const std::string& rel) {
  static const std::regex open(R"(^namespace ?([A-Za-z_:]*) \{$)"), close(R"(^\}  // namespace ?([A-Za-z_:]*)$)");
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  Scan scan;
  std::vector<Finding>& out = scan.findings;
  std::string open_name;
  bool inside = false, wrapped = false;
  int blocks = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (inside && !open_name.empty() && std::regex_match(lines[i], m, open) && !m[1].str().empty()) {
      scan.nested.insert(open_name + "::" + m[1].str());
    } else if (!inside && std::regex_match(lines[i], m, open)) {
      inside = true, open_name = m[1].str(), ++blocks;
      scan.file_scope.emplace_back(open_name, int(i + 1));
      wrapped = !kForeign.count(open_name);
      if (wrapped && (i + 1 >= lines.size() || lines[i + 1] != "SHADOWLAB_ISA_BEGIN"))
        out.push_back({rel, int(i + 1), "namespace " + open_name + " does not open SHADOWLAB_ISA_BEGIN"});
    } else if (inside && std::regex_match(lines[i], m, close) && m[1].str() == open_name) {
      if (wrapped && (i == 0 || lines[i - 1] != "SHADOWLAB_ISA_END"))
        out.push_back({rel, int(i + 1), "namespace " + open_name + " does not close SHADOWLAB_ISA_END"});
      inside = false;
    }
  }
  if (inside) out.push_back({rel, int(lines.size()), "namespace " + open_name + " has no `}  // namespace` line"});
  if (blocks == 0) out.push_back({rel, 1, "no namespace block: the file's code would be shared by every set"});
  return scan;
}

std::vector<Finding> check_file(const fs::path& path, const std::string& rel) { return scan_file(path, rel).findings; }

// File-scope blocks that reopen, from outside, a namespace another file opens inside a set's namespace.
std::vector<Finding> mixed_forms(const std::vector<std::pair<std::string, Scan>>& scans) {
  std::set<std::string> nested;
  for (const auto& [rel, s] : scans) nested.insert(s.nested.begin(), s.nested.end());
  std::vector<Finding> out;
  for (const auto& [rel, s] : scans)
    for (const auto& [name, line] : s.file_scope)
      if (nested.count(name))
        out.push_back({rel, line, "namespace " + name + " is opened inside a set's namespace elsewhere: open it "
                                  "there too (namespace A { SHADOWLAB_ISA_BEGIN namespace B {)"});
  return out;
}

TEST(IsaNamespace, EveryBlockOfThePipelineLibrariesIsInTheSetsNamespace) {
  const fs::path root = SHADOWLAB_SOURCE_DIR;
  int files = 0;
  std::vector<Finding> findings;
  std::vector<std::pair<std::string, Scan>> scans;
  for (const std::string& folder : kIsaFolders)
    for (const auto& e : fs::directory_iterator(root / folder)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      const std::string rel = folder + "/" + e.path().filename().string();
      if (kShared.count(rel)) continue;
      ++files;
      scans.emplace_back(rel, scan_file(e.path(), rel));
      for (const Finding& f : scans.back().second.findings) findings.push_back(f);
    }
  for (const Finding& f : mixed_forms(scans)) findings.push_back(f);
  EXPECT_GT(files, 150);  // the folders were found
  for (const Finding& f : findings) ADD_FAILURE() << f.file << ":" << f.line << ": " << f.what;
}

// The check itself finds a block left outside, and one closed outside.
TEST(IsaNamespace, TheCheckFindsAnUnwrappedBlock) {
  const fs::path dir = fs::temp_directory_path() / "shadowlab_isa_namespace_test";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.h") << "#pragma once\nnamespace raster {\ninline int f() { return 1; }\n}  // namespace raster\n";
  std::ofstream(dir / "half.h") << "namespace raster {\nSHADOWLAB_ISA_BEGIN\nint g();\n}  // namespace raster\n";
  std::ofstream(dir / "good.h") << "namespace CLI {\nclass App;\n}  // namespace CLI\n\nnamespace cli {\n"
                                   "SHADOWLAB_ISA_BEGIN\nint h();\nSHADOWLAB_ISA_END\n}  // namespace cli\n";
  EXPECT_EQ(check_file(dir / "bad.h", "bad.h").size(), 2u);
  EXPECT_EQ(check_file(dir / "half.h", "half.h").size(), 1u);
  EXPECT_TRUE(check_file(dir / "good.h", "good.h").empty());
  // raster::detail opened inside the set's namespace in one file and at file scope in another.
  std::ofstream(dir / "inner.h") << "namespace raster {\nSHADOWLAB_ISA_BEGIN\nnamespace detail {\nint f();\n"
                                    "}  // namespace detail\nSHADOWLAB_ISA_END\n}  // namespace raster\n";
  std::ofstream(dir / "outer.cpp") << "namespace raster::detail {\nSHADOWLAB_ISA_BEGIN\nint f() { return 0; }\n"
                                      "SHADOWLAB_ISA_END\n}  // namespace raster::detail\n";
  const std::vector<std::pair<std::string, Scan>> scans = {{"inner.h", scan_file(dir / "inner.h", "inner.h")},
                                                           {"outer.cpp", scan_file(dir / "outer.cpp", "outer.cpp")}};
  EXPECT_TRUE(scans[0].second.findings.empty());
  EXPECT_TRUE(scans[1].second.findings.empty());
  ASSERT_EQ(mixed_forms(scans).size(), 1u);
  EXPECT_EQ(mixed_forms(scans)[0].file, "outer.cpp");
  fs::remove_all(dir);
}

}  // namespace
