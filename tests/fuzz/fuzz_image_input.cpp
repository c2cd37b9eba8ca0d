// Fuzz target: the reader behind `diff`, `inspect` and `check` (cli/image_input.cpp, compiled in): a PNG when
// the input starts with PNG's signature, otherwise an EXR, read whole as float pixels through OpenImageIO.
#include <cstring>

#include "cli/cli_common.h"
#include "cli/image_input.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const bool png = size >= 8 && std::memcmp(data, kPng, 8) == 0;
  fuzz::expect_clean_errors<cli::CliError>([&] {
    const std::filesystem::path path = fuzz::input_file(data, size, png ? "image.png" : "image.exr");
    const OIIO::ImageBuf buf = cli::read_image(path.string());
    (void)buf.spec();
  });
  return 0;
}
