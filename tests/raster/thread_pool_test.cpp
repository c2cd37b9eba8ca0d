// The worker pool (raster/thread_pool.h): every index runs exactly once at any thread count, and
// parallel_for_workers hands each call a worker slot below workers() that no other call holds at the same time,
// which is what lets the renderer keep scratch memory per worker without locks.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "raster/thread_pool.h"

using namespace raster;

TEST(ThreadPool, WorkersCountsTheCallingThreadAndIsOneInline) {
  EXPECT_EQ(ThreadPool(0).workers(), 1);
  EXPECT_EQ(ThreadPool(1).workers(), 1);
  EXPECT_EQ(ThreadPool(3).workers(), 3);
  EXPECT_EQ(ThreadPool(-1).workers(), hardware_threads());
}

TEST(ThreadPool, EveryIndexOnceOnASlotNoOtherCallHoldsMeanwhile) {
  for (const int threads : {0, 1, 2, 7, 16}) {
    ThreadPool pool(threads);
    const int workers = pool.workers();
    for (const size_t n : {size_t(0), size_t(1), size_t(5), size_t(3000)}) {
      std::vector<std::atomic<int>> runs(n);
      std::vector<std::atomic<int>> holders(static_cast<size_t>(workers));
      std::atomic<int> bad_slot{0}, overlaps{0};
      std::vector<std::atomic<int>> slot_used(static_cast<size_t>(workers));
      pool.parallel_for_workers(n, [&](size_t i, int w) {
        ++runs[i];
        if (w < 0 || w >= workers) {
          ++bad_slot;
          return;
        }
        ++slot_used[size_t(w)];
        if (holders[size_t(w)].fetch_add(1) != 0) ++overlaps;  // another call is inside with the same slot
        volatile unsigned spin = 0;
        for (int k = 0; k < 2000; ++k) spin = spin + unsigned(k);  // stay inside long enough to overlap
        holders[size_t(w)].fetch_sub(1);
      });
      for (size_t i = 0; i < n; ++i) ASSERT_EQ(runs[i].load(), 1) << threads << " threads, index " << i << " of " << n;
      EXPECT_EQ(bad_slot.load(), 0) << threads << " threads";
      EXPECT_EQ(overlaps.load(), 0) << threads << " threads";
      int total = 0;
      for (auto& u : slot_used) total += u.load();
      EXPECT_EQ(size_t(total), n);
      if (threads <= 1 && n > 0) {
        EXPECT_EQ(slot_used[0].load(), int(n)) << "inline pools run everything on slot 0";
      }
    }
  }
}

TEST(ThreadPool, ParallelForRunsEveryIndexAndRethrows) {
  ThreadPool pool(2);
  std::vector<std::atomic<int>> runs(1000);
  pool.parallel_for(runs.size(), [&](size_t i) { ++runs[i]; });
  for (auto& r : runs) EXPECT_EQ(r.load(), 1);
  EXPECT_THROW(pool.parallel_for(100, [](size_t i) {
    if (i == 37) throw std::runtime_error("index 37");
  }),
               std::runtime_error);
}
