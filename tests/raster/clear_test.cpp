// DepthTarget::clear() as a flag until first use: a draw clears every tile of the padded target on its workers
// (inside and outside the draw's rectangle, with or without a back end that touches depth), any access through
// the target clears it whole first, and the output is bit for bit that of an eager clear, at 0, 1, 2, 7 and 16
// threads. Also the front end's split into chunks, which may not change any bit, and colour targets cleared on
// a pool's workers (parallel_clear.h).
#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "bench/triangle_soup.h"
#include "raster/parallel_clear.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;

namespace {

// Every texel of the padded target (rows and columns past the size included) holds `raw`.
bool all_texels(const DepthTarget& d, uint32_t raw) {
  for (int y = 0; y < d.padded_height(); ++y)
    for (int x = 0; x < d.pitch(); ++x) {
      const uint32_t v = d.format() == DepthFormat::d16 ? d.row<uint16_t>(y)[x] : d.row<uint32_t>(y)[x];
      if (v != raw) return false;
    }
  return true;
}

// A target whose memory holds garbage (a previous draw), then a pending clear to `z`.
DepthTarget dirty_then_cleared(int w, int h, DepthFormat f, float z) {
  DepthTarget d(w, h, f);
  for (int y = 0; y < d.padded_height(); ++y)
    for (int x = 0; x < d.pitch(); ++x) {
      if (f == DepthFormat::d16) d.row<uint16_t>(y)[x] = uint16_t(x * 7 + y);
      else d.row<uint32_t>(y)[x] = uint32_t(x * 7919 + y * 104729);
    }
  d.clear(z);
  return d;
}

}  // namespace

TEST(Clear, AccessThroughTheTargetResolvesIt) {
  DepthTarget d = dirty_then_cleared(100, 70, DepthFormat::d24, 0.5f);
  EXPECT_EQ(d.raw(99, 69), 8388608u);  // round(0.5 · 16777215)
  EXPECT_TRUE(all_texels(d, 8388608u));
  DepthTarget e = dirty_then_cleared(33, 65, DepthFormat::d16, 1.0f);
  const DepthTarget copy = e;  // a copy sees the clear too
  EXPECT_TRUE(all_texels(copy, 65535u));
  EXPECT_TRUE(all_texels(e, 65535u));
}

TEST(Clear, DrawsClearEveryTileOnTheWorkers) {
  const auto soup = bench::make_soup(3000, 40.0, 300, 5);
  for (DepthFormat fmt : {DepthFormat::d16, DepthFormat::d24, DepthFormat::d32f}) {
    for (int threads : {0, 1, 2, 7, 16}) {
      Renderer r(threads);
      // A scissored draw: tiles outside the scissor must be cleared too.
      DrawState s;
      s.scissor = Rect{70, 80, 100, 90};
      DepthTarget lazy = dirty_then_cleared(300, 200, fmt, 0.75f);
      DepthTarget eager = dirty_then_cleared(300, 200, fmt, 0.75f);
      eager.resolve_clear();
      r.draw(RenderTargets{&lazy}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions), soup.indices);
      r.draw(RenderTargets{&eager}, s, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions), soup.indices);
      EXPECT_EQ(rtest::hash_depth(lazy), rtest::hash_depth(eager)) << to_string(fmt) << " threads " << threads;
      EXPECT_EQ(lazy.raw(0, 0), eager.raw(0, 0));
      EXPECT_EQ(lazy.raw(299, 199), eager.raw(299, 199));

      // A draw of nothing, and a draw without a depth test, still leave the target cleared.
      DepthTarget empty = dirty_then_cleared(130, 64, fmt, 0.25f);
      r.draw(RenderTargets{&empty}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>());
      const uint32_t quarter = fmt == DepthFormat::d16   ? 16384u
                               : fmt == DepthFormat::d24 ? 4194304u
                                                         : std::bit_cast<uint32_t>(0.25f);
      EXPECT_TRUE(all_texels(empty, quarter)) << to_string(fmt) << " threads " << threads;
      DepthTarget untested = dirty_then_cleared(130, 64, fmt, 0.25f);
      DrawState no_test;
      no_test.depth_test = false;
      r.draw(RenderTargets{&untested}, no_test, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions),
             soup.indices);
      EXPECT_TRUE(all_texels(untested, quarter)) << to_string(fmt) << " threads " << threads;
    }
  }
}

// The front end splits a draw into chunks by triangle count and thread count (renderer.h, chunk_triangles):
// few large triangles over many threads make many small chunks, and the maps stay the same bits.
TEST(Clear, ChunkSplitChangesNoBit) {
  EXPECT_EQ(detail::chunk_triangles(20000, 16), 313u);  // 64 chunks
  EXPECT_EQ(detail::chunk_triangles(20000, 2), 2500u);
  EXPECT_EQ(detail::chunk_triangles(1000000, 2), detail::kMaxChunkTriangles);
  EXPECT_EQ(detail::chunk_triangles(100, 16), detail::kMinChunkTriangles);
  const auto soup = bench::make_soup(4000, 2000.0, 512, 9);
  uint64_t first = 0;
  for (int threads : {0, 1, 2, 7, 16}) {
    Renderer r(threads);
    DepthTarget d(512, 512, DepthFormat::d32f);
    d.clear(1.0f);
    r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions), soup.indices);
    EXPECT_EQ(r.last_timings().chunks, (4000 + detail::chunk_triangles(4000, threads) - 1) /
                                           detail::chunk_triangles(4000, threads));
    const uint64_t h = rtest::hash_depth(d);
    if (threads == 0) first = h;
    EXPECT_EQ(h, first) << "threads " << threads;
  }
}

// ColorTarget::clear stores one texel as write() does and copies it over the whole padded storage, for every
// format (RGBA8, and float targets of four, two and one channels): every texel reads back the cleared value.
// A 512² target is large enough to be mapped on its own, so copying by the wrong texel size would run past it.
TEST(Clear, ColorTargetsOfEveryFormatHoldTheClearedValueEverywhere) {
  for (ColorFormat f : {ColorFormat::rgba8, ColorFormat::rgba32f, ColorFormat::rg32f, ColorFormat::r32f}) {
    for (const glm::vec4 c : {glm::vec4(0.0f), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)}) {
      ColorTarget one(1, 1, f);
      one.write(0, 0, c);
      const glm::vec4 expected = one.read(0, 0);
      ColorTarget t(509, 511, f);
      t.clear(c);
      size_t wrong = 0;
      for (int y = 0; y < t.padded_height(); ++y)
        for (int x = 0; x < t.pitch(); ++x) wrong += t.read(x, y) != expected;
      EXPECT_EQ(wrong, 0u) << "format " << int(f) << ", clear " << c.r;
    }
  }
}

// clear_on_workers (raster/parallel_clear.h) stores the bytes ColorTarget::clear stores, over the whole padded
// storage (every row, padding included), for every format, sRGB, zero and non-zero values, at 0, 1, 2 and 7 threads.
TEST(Clear, ColorTargetsClearedOnWorkersHoldTheBytesOfTheSerialClear) {
  for (ColorFormat f : {ColorFormat::rgba8, ColorFormat::rgba32f, ColorFormat::rg32f, ColorFormat::r32f}) {
    for (const glm::vec4 c : {glm::vec4(0.0f), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f), glm::vec4(2.0f, -1.0f, 0.1f, 0.3f)}) {
      for (bool srgb : {false, true}) {
        if (srgb && f != ColorFormat::rgba8) continue;
        ColorTarget serial(509, 1031, f, srgb);
        serial.clear(c);
        const size_t row_bytes = size_t(serial.pitch()) * bytes_per_texel(f);
        auto row = [&](ColorTarget& t, int y) {
          return t.channels() > 0 ? static_cast<const void*>(t.row32f(y)) : static_cast<const void*>(t.row8(y));
        };
        for (int threads : {0, 1, 2, 7}) {
          ThreadPool pool(threads);
          ColorTarget t(509, 1031, f, srgb);
          t.clear(glm::vec4(0.9f, 0.8f, 0.7f, 0.6f));  // something else first, so every byte must be rewritten
          clear_on_workers(t, c, pool);
          int wrong_rows = 0;
          for (int y = 0; y < t.padded_height(); ++y) wrong_rows += std::memcmp(row(t, y), row(serial, y), row_bytes) != 0;
          EXPECT_EQ(wrong_rows, 0) << "format " << int(f) << ", clear " << c.r << ", srgb " << srgb << ", threads "
                                   << threads;
        }
      }
    }
  }
}
