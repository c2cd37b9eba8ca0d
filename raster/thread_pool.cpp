// ThreadPool over a oneTBB task arena limited to the requested concurrency (see thread_pool.h).
#include "raster/thread_pool.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

struct ThreadPool::Impl {
  // More threads than cores is allowed (a user oversubscribing on purpose): oneTBB's worker limit, by default
  // the core count, is raised for this pool's lifetime so the request is honoured instead of warned about.
  explicit Impl(int n)
      : limit(n > hardware_threads() ? std::make_unique<tbb::global_control>(
                                           tbb::global_control::max_allowed_parallelism, size_t(n))
                                     : nullptr),
        arena(n) {}
  std::unique_ptr<tbb::global_control> limit;
  tbb::task_arena arena;
};

int hardware_threads() { return std::max(1, int(std::thread::hardware_concurrency())); }

ThreadPool::ThreadPool(int threads) : threads_(threads < 0 ? hardware_threads() : threads) {
  if (threads_ > 0) impl_ = std::make_unique<Impl>(threads_);
}

ThreadPool::~ThreadPool() = default;

void ThreadPool::parallel_for(size_t n, const std::function<void(size_t)>& fn) {
  parallel_for_workers(n, [&](size_t i, int) { fn(i); });
}

void ThreadPool::parallel_for_workers(size_t n, const std::function<void(size_t, int)>& fn) {
  if (n == 0) return;
  if (!impl_ || n == 1) {
    for (size_t i = 0; i < n; ++i) fn(i, 0);
    return;
  }
  impl_->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        // The thread's slot in this arena, below the arena's concurrency (threads_).
                        const int w = tbb::this_task_arena::current_thread_index();
                        if (w < 0 || w >= threads_)
                          throw std::logic_error("ThreadPool: worker slot " + std::to_string(w) + " outside [0, " +
                                                 std::to_string(threads_) + ")");
                        for (size_t i = r.begin(); i != r.end(); ++i) fn(i, w);
                      },
                      tbb::simple_partitioner());
  });
}

SHADOWLAB_ISA_END
}  // namespace raster
