// Binning (raster/bins.h) and the draw's phase timings (renderer.h, DrawTimings): the non-temporal scatter of
// large depth-only draws writes the very records the plain copy writes, a draw large enough to take it gives the
// bits of the same triangles drawn in pieces too small to take it, at 0, 1, 2, 7 and 16 threads, and the busy
// times the draw reports are real task time that fits in the workers' wall time.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "bench/triangle_soup.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;

namespace {

// Records with random boxes over a 10 × 7 tile grid: many inside one tile, some across several, a few across
// the whole grid; every field filled so a wrongly copied half line shows.
std::vector<DepthSetup> random_records(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> x(0, 10 * kTileSize - 1), y(0, 7 * kTileSize - 1), extent(0, 3 * kTileSize);
  std::uniform_int_distribution<int32_t> any(-1000000, 1000000);
  std::vector<DepthSetup> out(n);
  for (size_t i = 0; i < n; ++i) {
    DepthSetup& d = out[i];
    for (int k = 0; k < 3; ++k) d.a[k] = any(rng), d.b[k] = any(rng), d.f0[k] = any(rng);
    const int big = i % 97 == 0 ? 10 * kTileSize : 0;
    d.min_x = int16_t(x(rng)), d.min_y = int16_t(y(rng));
    d.max_x = int16_t(std::min(10 * kTileSize - 1, d.min_x + (i % 3 == 0 ? extent(rng) : 4) + big));
    d.max_y = int16_t(std::min(7 * kTileSize - 1, d.min_y + (i % 5 == 0 ? extent(rng) : 3) + big));
    d.z_a0 = float(any(rng)), d.dzdx = float(i), d.dzdy = -float(i), d.z_offset = 0.5f;
    d.full = uint32_t(i);
  }
  return out;
}

}  // namespace

// The non-temporal path is the one-line record's (bins.h takes it only for 64-byte records aligned to 64); the
// scalar set's stream_line is a plain copy, so this compares the AVX2 set's stores with the copy.
static_assert(sizeof(DepthSetup) == 64 && alignof(DepthSetup) == 64);

TEST(Bins, StreamedScatterWritesTheRecordsOfThePlainCopy) {
  const TileGrid grid{10, 7};
  const auto records = random_records(5000, 3);
  ChunkBins<DepthSetup> plain, streamed;
  Staging<DepthSetup> staging;  // one worker's, set up and binned one chunk after the other
  plain.reset(grid, staging);
  for (const DepthSetup& d : records) plain.add(d, grid);
  plain.bin(grid, false);
  streamed.reset(grid, staging);
  for (const DepthSetup& d : records) streamed.add(d, grid);
  streamed.bin(grid, true);
  ASSERT_EQ(plain.offsets, streamed.offsets);
  ASSERT_EQ(plain.binned.size(), streamed.binned.size());
  EXPECT_GT(plain.binned.size(), records.size());  // some records went to several tiles
  EXPECT_EQ(std::memcmp(plain.binned.data(), streamed.binned.data(), plain.binned.size() * sizeof(DepthSetup)), 0);
  // Each tile's slice holds the records touching it, in submission order.
  const int tile = 3 * grid.tiles_x + 4;
  uint32_t at = plain.offsets[size_t(tile)];
  for (const DepthSetup& d : records) {
    if ((d.min_x >> kTileSizeLog2) <= 4 && (d.max_x >> kTileSizeLog2) >= 4 && (d.min_y >> kTileSizeLog2) <= 3 &&
        (d.max_y >> kTileSizeLog2) >= 3) {
      ASSERT_LT(at, plain.offsets[size_t(tile) + 1]);
      ASSERT_EQ(streamed.binned[at++].full, d.full);
    }
  }
  EXPECT_EQ(at, plain.offsets[size_t(tile) + 1]);
}

// A set-up batch's visible lanes handed over together (add_lanes, the depth-only front end's path) stage and bin
// exactly as the same records added one at a time: random lane masks, none, some and all of eight.
TEST(Bins, LanesStageTheRecordsOfOneAtATime) {
  const TileGrid grid{10, 7};
  const auto records = random_records(4000, 9);
  std::mt19937 rng(4);
  ChunkBins<DepthSetup> one, lanes;
  Staging<DepthSetup> staging_one, staging_lanes;
  one.reset(grid, staging_one);
  lanes.reset(grid, staging_lanes);
  size_t kept = 0;
  for (size_t g = 0; g + 8 <= records.size(); g += 8) {
    const unsigned mask = g % 80 == 0 ? 0xFFu : g % 88 == 8 ? 0u : unsigned(rng()) & 0xFFu;
    for (int l = 0; l < 8; ++l)
      if (mask >> l & 1u) one.add(records[g + size_t(l)], grid), ++kept;
    lanes.add_lanes(records.data() + g, mask, grid);
  }
  ASSERT_EQ(staging_lanes.size(), kept);
  ASSERT_EQ(std::memcmp(staging_one.data(), staging_lanes.data(), kept * sizeof(DepthSetup)), 0);
  one.bin(grid);
  lanes.bin(grid);
  ASSERT_EQ(one.offsets, lanes.offsets);
  ASSERT_EQ(one.binned.size(), lanes.binned.size());
  EXPECT_GT(one.binned.size(), kept);  // some records went to several tiles
  EXPECT_EQ(std::memcmp(one.binned.data(), lanes.binned.data(), one.binned.size() * sizeof(DepthSetup)), 0);
}

// 40 000 triangles of ~60 px bin with non-temporal stores (detail::kStreamBinsBytes); the same triangles drawn
// as five draws of 8 000 (below the threshold) bin with plain copies. Depth LESS in submission order: same bits.
TEST(Bins, LargeDrawsBinnedPastTheCachesGiveTheBitsOfSmallDraws) {
  constexpr size_t kTris = 40000, kPiece = 8000;
  ASSERT_GE(kTris * sizeof(DepthSetup), detail::kStreamBinsBytes);
  ASSERT_LT(kPiece * sizeof(DepthSetup), detail::kStreamBinsBytes);
  const auto soup = bench::make_soup(kTris, 60.0, 512, 21);
  auto draw = [&](Renderer& r, DepthTarget& d, size_t first, size_t count) {
    r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions),
           std::span<const uint32_t>(soup.indices).subspan(3 * first, 3 * count));
  };
  Renderer pieces_renderer(2);
  DepthTarget pieces(512, 512, DepthFormat::d32f);
  pieces.clear(1.0f);
  for (size_t first = 0; first < kTris; first += kPiece) draw(pieces_renderer, pieces, first, kPiece);
  const uint64_t expected = rtest::hash_depth(pieces);
  for (int threads : {0, 1, 2, 7, 16}) {
    Renderer r(threads);
    DepthTarget d(512, 512, DepthFormat::d32f);
    d.clear(1.0f);
    draw(r, d, 0, kTris);
    EXPECT_EQ(rtest::hash_depth(d), expected) << "threads " << threads;
  }
}

// Busy time is task time summed over workers: above zero for both phases of a real draw, and at most the
// workers' wall time (threads × the phase's wall time; the calling thread alone when inline).
TEST(DrawTimings, BusyTimeFitsInTheWorkersWallTime) {
  const auto soup = bench::make_soup(30000, 40.0, 1024, 5);
  for (int threads : {0, 2, 4}) {
    Renderer r(threads);
    DepthTarget d(1024, 1024, DepthFormat::d32f);
    d.clear(1.0f);
    r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup.positions),
           soup.indices);
    const DrawTimings& t = r.last_timings();
    const double workers = std::max(threads, 1);
    EXPECT_GT(t.front_busy_ms, 0.0) << threads;
    EXPECT_GT(t.back_busy_ms, 0.0) << threads;
    EXPECT_GE(t.back_busy_ms, t.clear_cpu_ms) << threads;  // the clear runs inside the back end's tasks
    EXPECT_LE(t.front_busy_ms, workers * t.front_ms * 1.0001 + 1e-3) << threads;
    EXPECT_LE(t.back_busy_ms, workers * t.back_ms * 1.0001 + 1e-3) << threads;
  }
}
