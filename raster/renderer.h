// The pipeline's entry point: a Renderer owns the worker pool and per-draw scratch, and draw<Shader>() runs one
// indexed triangle draw through the stages — vertex shading, primitive assembly + clipping + setup + binning
// (front end, in chunks), then tile execution (back end, one tile per task). Every stage is deterministic.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "raster/binned_chunk.h"
#include "raster/bins.h"
#include "raster/chunk_front_end.h"
#include "raster/clip.h"
#include "raster/depth_setup.h"
#include "raster/depth_stage.h"
#include "raster/draw_stats.h"
#include "raster/fragment_stage.h"
#include "raster/hiz.h"
#include "raster/scratch.h"
#include "raster/setup.h"
#include "raster/shader.h"
#include "raster/state.h"
#include "raster/target.h"
#include "raster/thread_pool.h"
#include "raster/tile_execution.h"
#include "raster/vertex_batch.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// What a draw renders into. Either may be null; when both are set they must have the same size.
struct RenderTargets {
  DepthTarget* depth = nullptr;
  ColorTarget* color = nullptr;
};

// Where the last draw's time went (wall clock on the calling thread, milliseconds): the front end (vertex
// stage, clipping, setup, binning) and the back end (tile execution, including the clear of each tile that a
// pending DepthTarget::clear() leaves to the draw); clear_cpu_ms is the time the workers spent clearing tiles,
// summed over workers (0 when no clear was pending). front_busy_ms and back_busy_ms are the time the workers spent
// inside each phase's tasks, summed over workers: busy / (threads × wall) is the share of the phase's wall time
// its workers were at work (the rest is waiting for work, start-up and the serial steps between tasks).
struct DrawTimings {
  double front_ms = 0, back_ms = 0, clear_cpu_ms = 0;
  double front_busy_ms = 0, back_busy_ms = 0;
  size_t chunks = 0;  // front-end chunks the draw was split into
};

class Renderer {
 public:
  // threads < 0: the hardware's; 0: everything inline on the calling thread.
  explicit Renderer(int threads = -1) : pool_(threads) {}

  int threads() const { return pool_.threads(); }
  ThreadPool& pool() { return pool_; }
  const DrawTimings& last_timings() const { return timings_; }

  // Draws an indexed triangle list (three indices per triangle); `indices` empty means non-indexed
  // (vertices 3i, 3i+1, 3i+2). The shader is copied once per draw (the snapshot), as is the state.
  template <VertexShader Shader>
  DrawStats draw(RenderTargets targets, const DrawState& state, const Shader& shader,
                 std::span<const typename Shader::Vertex> vertices, std::span<const uint32_t> indices = {});

 private:
  // What a chunk's front end needs only while its task runs, kept per worker (ThreadPool::parallel_for_workers)
  // and reused from one chunk to the next: the set-up records until they are binned, and a depth-only chunk's
  // outcodes and window vertices of its vertex range. Per chunk, a draw of 10^6 small triangles spread these
  // over ~150 MB of pages touched once each; per worker they are a few hot megabytes. Measured on the 2-core
  // AMD EPYC (Zen 5), AVX-512 path, at 2 threads beside llvmpipe (2026-11-29, seven runs each, alternating): the
  // front end of 10^6 triangles of ~10 px took 16–50 ms before and 15–24 ms after (README).
  struct WorkerScratch {
    Staging<TriangleSetup> setups;
    Staging<DepthSetup> depth_setups;
    ScratchBuffer codes, win;
  };

  // Carries out a pending clear of `depth` (the stored value `raw`), one tile per task.
  void clear_tiles(DepthTarget& depth, uint32_t raw);

  ThreadPool pool_;
  DrawTimings timings_;
  ScratchBuffer post_, win_, codes_;
  std::vector<std::unique_ptr<BinnedChunk>> chunks_;  // kept from draw to draw, with their memory
  std::vector<std::unique_ptr<WorkerScratch>> workers_;  // one per pool worker
};

namespace detail {

inline constexpr size_t kVertexBatch = 8192;
// The front end splits a draw into chunks of consecutive triangles, at least kChunksPerWorker per worker so that
// a draw of few (large) triangles still spreads over every worker, and no larger than kMaxChunkTriangles (the
// setups of one chunk stay in cache while they are binned) nor smaller than kMinChunkTriangles (each chunk has
// per-tile counters to sum and walk). The split changes no output: tiles execute the chunks in order.
inline constexpr size_t kMaxChunkTriangles = 8192;
inline constexpr size_t kMinChunkTriangles = 256;
inline constexpr size_t kChunksPerWorker = 4;
// A depth-only draw whose triangles, counted as submitted, would take at least this many bytes of one-line
// records (ntri × sizeof(DepthSetup)) bins them with non-temporal stores (ChunkBins::bin): its records are out
// of the caches by the time the tiles read them anyway, and the scatter over every tile's slice no longer reads
// each line before writing it. Measured on the 2-core AMD EPYC at 2 threads (2026-11-27, three runs each): front
// end of 10^6 triangles of ~10 px 53-63 -> 37-45 ms, of 2·10^4 of ~2000 px 3.0-3.3 -> 1.8-2.0 ms, the back ends
// unchanged within the noise. Smaller draws keep cached records.
inline constexpr size_t kStreamBinsBytes = size_t(1) << 20;
inline size_t chunk_triangles(size_t ntri, int threads) {
  const size_t chunks = kChunksPerWorker * size_t(std::max(threads, 1));
  return std::clamp((ntri + chunks - 1) / chunks, kMinChunkTriangles, kMaxChunkTriangles);
}

void check_draw(const RenderTargets& t, const DrawState& s, size_t vertices, size_t indices);

}  // namespace detail

template <VertexShader Shader>
DrawStats Renderer::draw(RenderTargets targets, const DrawState& state_in, const Shader& shader_in,
                         std::span<const typename Shader::Vertex> vertices, std::span<const uint32_t> indices) {
  using V = typename Shader::Varyings;
  using CV = ClipVertex<V>;
  constexpr bool kShaded = HasFragmentStage<Shader>;
  using Record = typename ChunkFrontEnd<Shader>::Record;  // what bins carry (BinnedChunk)
  auto staging_of = [](WorkerScratch& ws) -> Staging<Record>& {  // the worker's array for records before binning
    if constexpr (kShaded) return ws.setups;
    else return ws.depth_setups;
  };

  using Clock = std::chrono::steady_clock;
  const auto t_start = Clock::now();
  timings_ = DrawTimings{};
  // Runs one task of a phase, adding its time to the phase's busy sum (DrawTimings).
  std::atomic<int64_t> front_busy_ns{0}, back_busy_ns{0};
  auto timed = [](std::atomic<int64_t>& sum, auto&& task) {
    const auto t0 = Clock::now();
    task();
    sum.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count(),
                  std::memory_order_relaxed);
  };
  detail::check_draw(targets, state_in, vertices.size(), indices.size());
  const DrawState state = state_in;  // snapshot
  const Shader shader = shader_in;   // snapshot
  const int width = targets.depth ? targets.depth->width() : targets.color->width();
  const int height = targets.depth ? targets.depth->height() : targets.color->height();
  const DepthFormat format = targets.depth ? targets.depth->format() : DepthFormat::d32f;
  const SetupParams sp = make_setup_params(state, width, height, format);
  const ClipPlanes planes =
      make_clip_planes(state.depth_clamp, sp.vp_half_w, sp.vp_center_x, sp.vp_half_h, sp.vp_center_y);
  const size_t nv = vertices.size();
  const size_t ntri = indices.empty() ? nv / 3 : indices.size() / 3;
  if (ntri == 0 || sp.clip.empty()) {
    if (targets.depth)
      if (const auto raw = targets.depth->take_pending_clear()) clear_tiles(*targets.depth, *raw);
    return DrawStats{.triangles = ntri, .rejected = ntri};
  }

  // ---- Vertex stage: the shader per vertex (shader.h: a pure function), then outcodes and window space.
  // The shader runs one vertex at a time; the clip test and viewport transform eight at a time (vertex_batch.h).
  // Depth-only draws keep no clip-space vertices: the few triangles that need clipping run the shader again
  // on their vertices (a const function of the vertex and the snapshot), which saves writing them all.
  // shade_vertices(begin, end, codes, win) fills codes[i − begin] and win[i − begin] for vertices [begin, end).
  CV* post = kShaded ? post_.get<CV>(nv) : nullptr;  // depth-only draws keep no clip-space vertices
  const VertexBatch fixed_function(planes, sp, detail::kInvalidVertex);
  auto shade_vertices = [&](size_t begin, size_t end, unsigned* codes, WindowVertex* win) {
    // Vertex i's clip-space position: the shader's result, kept for clipping and interpolation in shaded draws.
    auto position = [&](size_t i) {
      if constexpr (kShaded) {
        CV& cv = post[i];
        cv.pos = shader.vertex(vertices[i], cv.var);
        return cv.pos;
      } else {
        V unused;
        return shader.vertex(vertices[i], unused);
      }
    };
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
    for (size_t i0 = begin; i0 < end; i0 += 8) {
      const int n = int(std::min<size_t>(8, end - i0));
      // The coordinates in lanes: deinterleave_rows4 takes the four-float records 0–3 as its first "row" and
      // 4–7 as its second, two records per vector. A full batch takes each pair of positions straight from the
      // shader's results (a round trip through memory, written in 8-byte halves and read back 32 bytes at a time,
      // stalls the loads); the last, partial one goes through an array whose lanes past the end repeat the first.
      simd::VecF32 x, y, z, w, v[4];
      if (n == 8) {
        for (int k = 0; k < 4; ++k) {
          const glm::vec4 a = position(i0 + 2 * k), b = position(i0 + 2 * k + 1);
          v[k] = simd::load_rows4(&a.x, &b.x);
        }
      } else {
        alignas(32) glm::vec4 pos[8];
        for (int l = 0; l < n; ++l) pos[l] = position(i0 + size_t(l));
        for (int l = n; l < 8; ++l) pos[l] = pos[0];
        for (int k = 0; k < 4; ++k) v[k] = simd::VecF32::load(&pos[2 * k].x);
      }
      simd::deinterleave_rows4(v[0], v[1], v[2], v[3], x, y, z, w);
      fixed_function.run(x, y, z, w, n, codes + (i0 - begin), win + (i0 - begin));
    }
  };
  WindowVertex* all_win = nullptr;
  unsigned* all_codes = nullptr;
  auto shade_all_vertices = [&] {
    all_win = win_.get<WindowVertex>(nv);
    all_codes = codes_.get<unsigned>(nv);
    pool_.parallel_for((nv + detail::kVertexBatch - 1) / detail::kVertexBatch, [&](size_t b) {
      timed(front_busy_ns, [&] {
        const size_t begin = b * detail::kVertexBatch, end = std::min(nv, begin + detail::kVertexBatch);
        shade_vertices(begin, end, all_codes + begin, all_win + begin);
      });
    });
  };

  // ---- Front end: assembly, clipping, setup, binning, in chunks of consecutive triangles.
  const TileGrid grid = TileGrid::for_size(width, height);
  const size_t chunk_tris = detail::chunk_triangles(ntri, pool_.threads());
  const size_t nchunks = (ntri + chunk_tris - 1) / chunk_tris;
  timings_.chunks = nchunks;
  const bool stream_bins = !kShaded && ntri * sizeof(DepthSetup) >= detail::kStreamBinsBytes;
  while (chunks_.size() < nchunks) chunks_.push_back(std::make_unique<BinnedChunk>());
  while (workers_.size() < size_t(pool_.workers())) workers_.push_back(std::make_unique<WorkerScratch>());
  const ChunkFrontEnd<Shader> front{shader, vertices, indices, sp, planes, post, grid, ntri, chunk_tris, stream_bins};
  // A depth-only draw whose chunks use disjoint, compact vertex ranges (a soup: each chunk owns its vertices)
  // shades each chunk's range inside the chunk's task, into the chunk's own small buffers, so window vertices
  // are used while still in cache instead of going through memory. Where the ranges overlap or hold unused
  // vertices (meshes share vertices between chunks), together more than nv + nv/8 vertices, the draw shades every
  // vertex once for the whole draw instead, as shaded draws always do. One chunk whose range is not compact
  // decides that, so the chunks still to be measured are skipped once one is found (`spread`): a mesh's index
  // buffer is then not read twice. Measured on the 2-core AMD EPYC (Zen 4), 2 threads: measuring every chunk of
  // the dragon's 871k triangles took 0.26–0.37 ms of its 8 ms front end (its 10 MB of indices read from memory),
  // stopping at its first chunk 0.06 ms.
  for (size_t c = 0; c < nchunks; ++c) chunks_[c]->pending = true;
  if constexpr (!kShaded) {
    // Whether a chunk was found whose vertices are not compact; whichever chunk finds it, the outcome is the same.
    std::atomic<bool> spread{false};
    pool_.parallel_for(nchunks, [&](size_t c) {
      if (spread.load(std::memory_order_relaxed)) return;
      timed(front_busy_ns, [&] {
        BinnedChunk& ch = *chunks_[c];
        const size_t first = c * chunk_tris, end = std::min(ntri, first + chunk_tris);
        uint32_t lo = uint32_t(3 * first), hi = uint32_t(3 * end - 1);  // a non-indexed draw's range
        if (!indices.empty()) {
          lo = ~0u, hi = 0;
          for (size_t i = 3 * first; i < 3 * end; ++i) lo = std::min(lo, indices[i]), hi = std::max(hi, indices[i]);
        }
        ch.range_lo = lo, ch.range_hi = hi;
        // Out-of-range indices take the whole-draw path too, whose front end reports them.
        if (!(hi < nv && hi - lo < 3 * chunk_tris)) spread.store(true, std::memory_order_relaxed);
      });
    });
    // Every chunk's range was measured unless `spread` is set (skipped chunks keep a previous draw's values).
    const bool compact = !spread.load(std::memory_order_relaxed);
    size_t shaded = 0;  // vertices the chunks would shade between them
    for (size_t c = 0; c < nchunks && compact; ++c) shaded += size_t(chunks_[c]->range_hi - chunks_[c]->range_lo) + 1;
    if (compact && shaded <= nv + nv / 8) {
      pool_.parallel_for_workers(nchunks, [&](size_t c, int w) {
        timed(front_busy_ns, [&] {
          BinnedChunk& ch = *chunks_[c];
          WorkerScratch& ws = *workers_[size_t(w)];
          const uint32_t lo = ch.range_lo, hi = ch.range_hi;
          unsigned* codes = ws.codes.get<unsigned>(hi - lo + 1);
          WindowVertex* win = ws.win.get<WindowVertex>(hi - lo + 1);
          shade_vertices(lo, size_t(hi) + 1, codes, win);
          front(c, ch, staging_of(ws), codes, win, lo, true);
          ch.pending = false;
        });
      });
    }
  }
  bool pending = false;
  for (size_t c = 0; c < nchunks; ++c) pending |= chunks_[c]->pending;
  if (pending) {
    shade_all_vertices();
    pool_.parallel_for_workers(nchunks, [&](size_t c, int w) {
      if (!chunks_[c]->pending) return;
      timed(front_busy_ns, [&] {
        front(c, *chunks_[c], staging_of(*workers_[size_t(w)]), all_codes, all_win, 0, false);
      });
    });
  }

  // ---- Back end: each tile executes its commands, chunk by chunk, in submission order. A pending clear of the
  // depth target is taken over here: every tile of the padded target is cleared by the worker that runs it, just
  // before its commands (tiles outside the draw's rectangle too), so the clear is spread over the workers and
  // the tile is in cache when its triangles are drawn.
  const auto t_back = Clock::now();
  timings_.front_ms = std::chrono::duration<double, std::milli>(t_back - t_start).count();
  const std::optional<uint32_t> clear_raw = targets.depth ? targets.depth->take_pending_clear() : std::nullopt;
  std::atomic<int64_t> clear_ns{0};
  bool tiles_ran = false;
  auto clear_tile = [&](int tx, int ty) {
    const auto c0 = Clock::now();
    targets.depth->fill_tile(*clear_raw, tx, ty);
    clear_ns.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - c0).count(),
                       std::memory_order_relaxed);
  };
  DrawStats stats;
  const std::span<const std::unique_ptr<BinnedChunk>> chunks(chunks_.data(), nchunks);
  for (const auto& ch : chunks) stats += ch->stats;
  const TilePlan plan = TilePlan::make(grid, sp.clip, targets.depth, clear_raw);
  const bool test = state.depth_test && targets.depth;
  const DepthFunc func = test ? state.depth_func : DepthFunc::always;
  const bool depth_write = test && state.depth_write && func != DepthFunc::never;  // NEVER writes nothing

  // One back end per depth format; the depth function is a run-time DepthCompare for shaded draws and, apart
  // from LESS and LEQUAL, for depth-only draws (dispatch_depth_only_func).
  dispatch_depth_format(format, [&]<DepthFormat F>() {
    auto run_tiles = [&](auto make_stage, bool use_hiz = false) {
      tiles_ran = true;
      pool_.parallel_for(plan.tasks(), [&](size_t k) {
        timed(back_busy_ns, [&] { execute_tile<Record>(plan, k, chunks, make_stage, use_hiz, clear_tile); });
      });
    };
    if constexpr (kShaded) {
      const DepthCompare compare(func);
      run_tiles([&](const BinnedChunk& ch, TileHiZ&) {
        return ShadedStage<Shader, F>{&shader,      ch.interps.view<TriangleInterp<V>>(),
                                      test ? targets.depth : nullptr, targets.color, compare, depth_write,
                                      state.color_write, state.blend};
      });
    } else if (targets.depth && test) {
      dispatch_depth_only_func(func, [&]<class Compare>(Compare compare) {
        auto depth_only = [&]<bool kWrite>() {
          using Stage = DepthOnlyStage<F, Compare, kWrite>;
          run_tiles([&](const BinnedChunk&, TileHiZ& hiz) { return Stage{targets.depth, &hiz, compare}; }, Stage::kHiZ);
        };
        if (depth_write) depth_only.template operator()<true>();
        else depth_only.template operator()<false>();
      });
    }
  });
  if (clear_raw && !tiles_ran)  // no back end ran over the depth target (no depth test): clear it alone
    pool_.parallel_for(size_t(grid.count()), [&](size_t k) {
      timed(back_busy_ns, [&] { clear_tile(int(k % size_t(grid.tiles_x)), int(k / size_t(grid.tiles_x))); });
    });
  timings_.back_ms = std::chrono::duration<double, std::milli>(Clock::now() - t_back).count();
  timings_.clear_cpu_ms = double(clear_ns.load()) * 1e-6;
  timings_.front_busy_ms = double(front_busy_ns.load()) * 1e-6;
  timings_.back_busy_ms = double(back_busy_ns.load()) * 1e-6;
  return stats;
}

SHADOWLAB_ISA_END
}  // namespace raster
