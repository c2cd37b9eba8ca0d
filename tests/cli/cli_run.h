// Running the built shadowlab executable from the end-to-end tests: one command line in a folder, its exit code
// and captured output, and the shape every bad-input run must have (exit 2, one line
// `shadowlab: error: WHERE: what`, no output file).
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace testsupport {

struct Outcome {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `shadowlab ARGS` in `dir` (a shell command line; arguments are quoted by the caller where needed).
// `prefix` goes in front of the executable: environment assignments ("NAME=value") and/or a wrapper command.
inline Outcome shadowlab(const std::filesystem::path& dir, const std::string& args, const std::string& prefix = "") {
  const std::string cmd =
      "cd '" + dir.string() + "' && " + prefix + " '" SHADOWLAB_CLI "' " + args + " >stdout.txt 2>stderr.txt";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stdout.txt"), slurp(dir / "stderr.txt")};
}

// A bad-input run: exit code 2, exactly one line `shadowlab: error: WHERE: what`, and no file named `out`.
inline void expect_bad_run(const std::filesystem::path& dir, const std::string& args, const std::string& where,
                           const std::string& out = "") {
  const Outcome r = shadowlab(dir, args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  EXPECT_THAT(r.err, ::testing::MatchesRegex("shadowlab: error: [^\n]+: [^\n]+\n")) << args;
  EXPECT_EQ(r.err.rfind("shadowlab: error: " + where + ": ", 0), 0u) << args << "\n" << r.err;
  if (!out.empty()) {
    EXPECT_FALSE(std::filesystem::exists(dir / out)) << args;
  }
}

}  // namespace testsupport
