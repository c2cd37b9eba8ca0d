// Fuzz target: a light matrix file for `shadowmap --light-matrix` (cli/light_matrix.cpp, compiled in).
#include "cli/cli_common.h"
#include "cli/light_matrix.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expect_clean_errors<cli::CliError>([&] {
    const std::filesystem::path path = fuzz::input_file(data, size, "light.json");
    (void)cli::read_light_matrices(path);
  });
  return 0;
}
