// Golden-image support for the frame-level regression tests: a content hash of an RGBA8 frame (FNV-1a of its
// bytes), the SHADOWLAB_GOLDEN_DUMP debug aid, and the check that a frame's hash is the same at 0, 1 and 2
// threads and equals the expected one, printing the new hash to paste after looking at the image when not.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scenes/frame/frame.h"
#include "raster/target.h"

namespace testsupport {

inline uint64_t frame_hash(const raster::ColorTarget& c) {
  uint64_t h = 1469598103934665603ull;
  for (int y = 0; y < c.height(); ++y) {
    const uint8_t* row = c.row8(y);
    for (int x = 0; x < c.width() * 4; ++x) h = (h ^ row[x]) * 1099511628211ull;
  }
  return h;
}

// SHADOWLAB_GOLDEN_DUMP=dir writes the frame as dir/NAME.ppm (binary PPM, top row first) to look at.
inline void dump_golden(const raster::ColorTarget& c, const std::string& name) {
  const char* dir = std::getenv("SHADOWLAB_GOLDEN_DUMP");
  if (!dir) return;
  std::FILE* f = std::fopen((std::string(dir) + "/" + name + ".ppm").c_str(), "wb");
  if (!f) return;
  std::fprintf(f, "P6\n%d %d\n255\n", c.width(), c.height());
  for (int y = c.height() - 1; y >= 0; --y)
    for (int x = 0; x < c.width(); ++x) std::fwrite(c.row8(y) + 4 * x, 1, 3, f);
  std::fclose(f);
}

// Fails the test, printing the hash to paste, when `actual` is not `expected`.
inline void expect_golden_hash(const std::string& name, uint64_t actual, uint64_t expected) {
  if (actual == expected) return;
  std::printf("golden %s: new hash 0x%016llxull\n", name.c_str(), static_cast<unsigned long long>(actual));
  ADD_FAILURE() << name << ": hash 0x" << std::hex << actual << " expected 0x" << expected;
}

// Renders the frame at 0, 1 and 2 threads (`check` looks at each), requires one hash for all three and that it
// is `expected`; the threads-0 frame is dumped on request.
template <class Check>
void expect_golden_frame(const std::string& name, uint64_t expected, const scenes::Scene& scene,
                         const frame::FrameConfig& options, Check check) {
  uint64_t first = 0;
  for (int threads : {0, 1, 2}) {
    raster::Renderer r(threads);
    const frame::Frame f = frame::render_frame(scene, options, r);
    check(f);
    const uint64_t h = frame_hash(f.color);
    if (threads == 0) {
      first = h;
      dump_golden(f.color, name);
    }
    EXPECT_EQ(h, first) << name << ": threads " << threads << " differ from threads 0";
  }
  expect_golden_hash(name, first, expected);
}

}  // namespace testsupport
