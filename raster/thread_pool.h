// The only place threads exist: a worker pool over oneTBB that runs an index range, each index exactly once,
// on any worker. threads = 0 runs the same code inline on the calling thread. Results never depend on which
// worker ran an index, because every index writes only its own data (a tile, a chunk).
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

class ThreadPool {
 public:
  // threads < 0: the hardware's concurrency; 0: inline, no worker threads; n > 0: at most n threads
  // (the calling thread counts as one of them).
  explicit ThreadPool(int threads = -1);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return threads_; }

  // Calls fn(i) for every i in [0, n), in parallel, and returns when all are done. Small grains go to idle
  // workers dynamically; exceptions thrown by fn are rethrown here.
  void parallel_for(size_t n, const std::function<void(size_t)>& fn);

 private:
  struct Impl;
  int threads_;
  std::unique_ptr<Impl> impl_;
};

// The hardware's thread count (at least 1).
int hardware_threads();

SHADOWLAB_ISA_END
}  // namespace raster
