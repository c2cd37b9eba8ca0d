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

  // How many workers run a parallel_for's indices (the calling thread included; 1 when inline).
  int workers() const { return threads_ > 0 ? threads_ : 1; }
  // As parallel_for, and fn(i, w) also gets the worker running index i, w in [0, workers()): no two calls with
  // the same w overlap, so memory kept per worker and indexed by w needs no lock, and stays in that worker's
  // caches from one index to the next. fn must not start parallel work of its own (a waiting worker could take
  // another index meanwhile).
  void parallel_for_workers(size_t n, const std::function<void(size_t, int)>& fn);

 private:
  struct Impl;
  int threads_;
  std::unique_ptr<Impl> impl_;
};

// The hardware's thread count (at least 1).
int hardware_threads();

SHADOWLAB_ISA_END
}  // namespace raster
