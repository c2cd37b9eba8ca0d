// Tile execution's plan (raster/tile_execution.h): which tiles a draw's back end runs, with and without a pending
// clear, and that the tasks clear every tile of the target exactly once whatever the draw's rectangle. What the
// tiles draw is checked end to end elsewhere (clear_test.cpp, conformance_test.cpp, coverage_test.cpp).
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "raster/renderer.h"

using namespace raster;

TEST(TilePlan, TilesOfTheDrawRectangle) {
  DepthTarget depth(300, 200, DepthFormat::d32f);
  const TileGrid grid = TileGrid::for_size(300, 200);  // 5 × 4 tiles of 64
  ASSERT_EQ(grid.tiles_x, 5);
  ASSERT_EQ(grid.tiles_y, 4);
  const PixelRect clip{70, 80, 169, 199};  // tiles x 1–2, y 1–3
  const TilePlan plan = TilePlan::make(grid, clip, &depth, std::nullopt);
  EXPECT_EQ(plan.tx0, 1);
  EXPECT_EQ(plan.tx1, 2);
  EXPECT_EQ(plan.ty0, 1);
  EXPECT_EQ(plan.ty1, 3);
  EXPECT_EQ(plan.task_x0(), 1);
  EXPECT_EQ(plan.task_y0(), 1);
  EXPECT_EQ(plan.task_cols(), 2);
  EXPECT_EQ(plan.task_rows(), 3);
  EXPECT_EQ(plan.tasks(), 6u);
  // A pending clear makes the tasks cover the whole target.
  const TilePlan cleared = TilePlan::make(grid, clip, &depth, 0x3F800000u);
  EXPECT_EQ(cleared.task_x0(), 0);
  EXPECT_EQ(cleared.task_y0(), 0);
  EXPECT_EQ(cleared.tasks(), 20u);
}

// With no records, each task only clears: every tile of the target once with a clear pending, none without.
TEST(TilePlan, TasksClearEveryTileOnce) {
  DepthTarget depth(300, 200, DepthFormat::d32f);
  const TileGrid grid = TileGrid::for_size(300, 200);
  std::vector<std::unique_ptr<BinnedChunk>> chunks;
  chunks.push_back(std::make_unique<BinnedChunk>());
  chunks[0]->depth_bins.offsets.assign(size_t(grid.count()) + 1, 0u);  // a chunk with nothing in any tile
  const std::span<const std::unique_ptr<BinnedChunk>> view(chunks.data(), chunks.size());
  int stages = 0;
  using Stage = DepthOnlyStage<DepthFormat::d32f, FixedDepthFunc<DepthFunc::less>, true>;
  auto make_stage = [&](const BinnedChunk&, TileHiZ& hiz) {
    ++stages;
    return Stage{&depth, &hiz, FixedDepthFunc<DepthFunc::less>{}};
  };
  for (const PixelRect clip : {PixelRect{70, 80, 169, 199}, PixelRect{0, 0, 299, 199}, PixelRect{299, 0, 299, 0}}) {
    for (const bool pending : {true, false}) {
      const TilePlan plan = TilePlan::make(grid, clip, &depth, pending ? std::optional<uint32_t>(0u) : std::nullopt);
      std::map<std::pair<int, int>, int> cleared;
      auto clear_tile = [&](int tx, int ty) { ++cleared[{tx, ty}]; };
      for (size_t k = 0; k < plan.tasks(); ++k)
        execute_tile<DepthSetup>(plan, k, view, make_stage, true, clear_tile);
      if (pending) {
        EXPECT_EQ(cleared.size(), size_t(grid.count()));
        for (const auto& [tile, n] : cleared) {
          EXPECT_EQ(n, 1) << tile.first << "," << tile.second;
          EXPECT_TRUE(tile.first >= 0 && tile.first < grid.tiles_x && tile.second >= 0 && tile.second < grid.tiles_y);
        }
      } else {
        EXPECT_TRUE(cleared.empty());
      }
    }
  }
  EXPECT_EQ(stages, 0);  // no tile had a record, so no stage was made
}
