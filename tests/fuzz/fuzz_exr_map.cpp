// Fuzz target: an EXR file as `inspect` reads a map: its channel names, then the map (pixels, matrices, passes)
// from its Z channel or, lacking one, its first channel.
#include <algorithm>

#include "scenes/io/exr_map.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expect_clean_errors([&] {
    const std::filesystem::path path = fuzz::input_file(data, size, "map.exr");
    const std::vector<std::string> channels = scenes::io::exr_channel_names(path);
    if (channels.empty()) return;
    const bool has_z = std::find(channels.begin(), channels.end(), "Z") != channels.end();
    const scenes::io::ExrMap map = scenes::io::read_exr_map(path, has_z ? "Z" : channels.front());
    // Touch every value, so a size that disagrees with the pixels shows as an out-of-bounds read.
    float sum = 0.0f;
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < map.width; ++x) sum += map.at(x, y);
    (void)sum;
  });
  return 0;
}
