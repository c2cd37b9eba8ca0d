// The pipeline's entry point: a Renderer owns the worker pool and per-draw scratch, and draw<Shader>() runs one
// indexed triangle draw through the stages — vertex shading, primitive assembly + clipping + setup + binning
// (front end, in chunks), then tile execution (back end, one tile per task). Every stage is deterministic.
#pragma once
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "raster/assembly.h"
#include "raster/bins.h"
#include "raster/clip.h"
#include "raster/coverage.h"
#include "raster/depth_setup.h"
#include "raster/depth_stage.h"
#include "raster/draw_stats.h"
#include "raster/fragment_stage.h"
#include "raster/hiz.h"
#include "raster/interpolation.h"
#include "raster/scratch.h"
#include "raster/setup.h"
#include "raster/setup_batch.h"
#include "raster/shader.h"
#include "raster/state.h"
#include "raster/target.h"
#include "raster/thread_pool.h"
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

// Invalid draw input (an index out of range, mismatched targets, a bad viewport). The message says which.
struct DrawError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
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
  // The front end's output for one chunk of consecutive triangles.
  struct Chunk {
    // The visible triangles, binned: TriangleSetup for shaded draws, DepthSetup for depth-only draws (whose
    // triangles too wide for it keep their TriangleSetup in `full`).
    ChunkBins<TriangleSetup> bins;
    ChunkBins<DepthSetup> depth_bins;
    ScratchBuffer full;
    size_t full_count = 0;
    ScratchBuffer interps;  // TriangleInterp<Varyings>, shaded draws only
    bool pending = true;    // the front end has still to run, with the draw's vertices
    uint32_t range_lo = 0, range_hi = 0;  // depth-only draws: the smallest and largest vertex index the chunk uses
    size_t interp_count = 0;
    DrawStats stats;
  };

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
  std::vector<std::unique_ptr<Chunk>> chunks_;
  std::vector<std::unique_ptr<WorkerScratch>> workers_;  // one per pool worker
};

namespace detail {

// One callable made of several lambdas, each serving the calls its parameters take.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // spelled out: clang 14 (the fuzzers' compiler) deduces no aggregate

inline constexpr size_t kVertexBatch = 8192;
// The front end splits a draw into chunks of consecutive triangles, at least kChunksPerWorker per worker so that
// a draw of few (large) triangles still spreads over every worker, and no larger than kMaxChunkTriangles (the
// setups of one chunk stay in cache while they are binned) nor smaller than kMinChunkTriangles (each chunk has
// per-tile counters to sum and walk). The split changes no output: tiles execute the chunks in order.
inline constexpr size_t kMaxChunkTriangles = 8192;
inline constexpr size_t kMinChunkTriangles = 256;
inline constexpr size_t kChunksPerWorker = 4;
inline constexpr unsigned kInvalidVertex = 1u << 31;
// A depth-only draw whose triangles, counted as submitted, would take at least this many bytes of one-line
// records (ntri × sizeof(DepthSetup)) bins them with non-temporal stores (ChunkBins::bin): its records are out
// of the caches by the time the tiles read them anyway, and the scatter over every tile's slice no longer reads
// each line before writing it. Measured on the 2-core AMD EPYC at 2 threads (2026-11-27, three runs each): front
// end of 10^6 triangles of ~10 px 53-63 -> 37-45 ms, of 2·10^4 of ~2000 px 3.0-3.3 -> 1.8-2.0 ms, the back ends
// unchanged within the noise. Smaller draws keep cached records.
inline constexpr size_t kStreamBinsBytes = size_t(1) << 20;
// Tile execution reads each tile's slice of a chunk's records in order, and those of a large draw come from
// memory (they were streamed there, see above); the dragon's back end stalled on each record's first field (13 %
// of its samples), presumably because a slice is often too short for the hardware's stream prefetcher to catch
// up. So the back end asks for the record this many places ahead as it takes each one (records of a triangle too
// wide for a DepthSetup, read from the chunk's side array, are not prefetched). Measured on the
// 2-core AMD EPYC (Zen 5), AVX-512 path, shadowlab alone at 2 threads, five runs each alternating: back end of
// (a) 12.2–14.3 → 10.9–11.1 ms, (c) 11.6–11.8 → 11.1–11.6 ms, (b) 8.8–8.9 → 8.6–8.7 ms; 4 ahead measured about
// the same ((a) 11.1–11.4 ms).
inline constexpr size_t kBinPrefetch = 8;
// A depth-only draw whose vertices are shaded once for the whole draw (a mesh whose chunks share vertices) reads
// each triangle's outcodes and window vertices at the mesh's indices, from arrays larger than the L2 cache and in
// an order no hardware prefetcher follows (the dragon's 871k triangles: 10.5 MB of window vertices, each chunk's
// indices spanning 165k vertices on average). So the batched front end asks for the outcodes and window vertices
// of the triangles this many places ahead as it assembles each group of eight. Measured on the 2-core AMD EPYC of
// the Zen 4 generation, AVX-512 path, shadowlab alone at 2 threads (2026-11-30, four to six rounds alternating,
// 15 repetitions each): the dragon's front end 9.36–9.73 → 8.86–9.06 ms (window vertices alone 9.18–9.34 ms); 8
// places ahead 9.00–9.08 ms, 32 and 64 like 16. Draws whose chunks shade their own vertices (soups) do not ask:
// theirs are in the chunk's small buffers, and asking cost the 10^6 small triangles' front end about 5 %.
inline constexpr size_t kVertexPrefetch = 16;
// Asks for the cache line holding `address`, given as an integer: the address may lie past any array (a prefetch
// never faults), where forming a pointer to it would not be allowed.
inline void prefetch_address(uintptr_t address) { __builtin_prefetch(reinterpret_cast<const void*>(address), 0, 3); }

// The lines of the depth tile a worker will likely clear next. A tile's clear (DepthTarget::fill_tile) is 16 KB
// of stores (d32f) in 64 rows a pitch apart, each store waiting for its line to come from memory, more lines than
// a core keeps in flight: on the 2-core Intel Xeon (family 6, model 167) the clear took 3.8 of the 18 ms of
// worker time of a draw of 2·10^4 triangles of 2,000 px. Workers mostly run tiles in index order (the pool hands
// out ranges of indices), so while a worker executes a cleared tile's records it asks for the next tile's rows,
// spread over the records (one row each, or more when the tile has fewer than 64), the records' work hiding the
// wait; a guess that misses costs only the lines asked for. Same bits. Measured on that Xeon, AVX-512 path, 2
// threads beside llvmpipe (bench/depth_pass_bench.cpp, five runs each): the clear's worker time 3.75–3.90 →
// 0.20–0.21 ms for those triangles, 3.22–3.38 → 0.27–0.30 ms for 10^6 triangles of 10 px, 1.94–2.07 → 1.04–1.11
// ms for the dragon (its empty tiles' clears run without records to hide them); see docs/performance-log.md.
struct NextTileRows {
  uintptr_t at = 0;   // the next row's first byte
  size_t pitch = 0;   // bytes from one row to the next
  int lines = 0;      // cache lines in a tile's row
  int left = 0;       // rows not asked for yet
  int per_record = 1;  // rows asked for per record: all of them over the tile's first 64 records or fewer
  void ask_rows() {
    for (int r = std::min(per_record, left); r > 0; --r, --left, at += pitch)
      for (int l = 0; l < lines; ++l) prefetch_address(at + uintptr_t(64 * l));
  }
};

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
  using Record = std::conditional_t<kShaded, TriangleSetup, DepthSetup>;  // what bins carry (see Chunk)
  auto bins_of = [](auto& ch) -> auto& {
    if constexpr (kShaded) return ch.bins;
    else return ch.depth_bins;
  };
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
  while (chunks_.size() < nchunks) chunks_.push_back(std::make_unique<Chunk>());
  while (workers_.size() < size_t(pool_.workers())) workers_.push_back(std::make_unique<WorkerScratch>());
  // One chunk's front end on the worker owning `ws`, reading vertex i's outcode and window position at
  // codes[i − base], win[i − base]. `in_range`: the chunk's indices are known to be below nv (its range was
  // measured), so none is tested again.
  auto front = [&](size_t c, WorkerScratch& ws, const unsigned* codes, const WindowVertex* win, uint32_t base,
                   bool in_range) {
    Chunk& ch = *chunks_[c];
    ChunkBins<Record>& bins = bins_of(ch);
    Staging<Record>& staging = staging_of(ws);
    bins.reset(grid, staging);
    ch.full_count = 0;
    ch.interp_count = 0;
    ch.stats = DrawStats{};
    const size_t end = std::min(ntri, (c + 1) * chunk_tris);
    staging.reserve(end - c * chunk_tris);
    // Bins a visible triangle's record: setup_triangle()'s, or a DepthSetup from the batch.
    auto keep = [&](const auto& t) {
      ++ch.stats.setups;
      if constexpr (std::is_same_v<std::decay_t<decltype(t)>, Record>) {
        bins.add(t, grid);
      } else if constexpr (!kShaded) {  // a depth-only draw's triangle set up by setup_triangle()
        DepthSetup d = pack_depth_setup(t);  // the box is right in any case; the edges only when it fits
        if (!fits_depth_setup(t)) {
          d.full = uint32_t(ch.full_count);
          ch.full_count = ch.full.append(ch.full_count, t);
        }
        bins.add(d, grid);
      }
    };
    auto count = [&](SetupResult r) {
      switch (r) {
        case SetupResult::visible: return true;
        case SetupResult::culled: ++ch.stats.culled; break;
        case SetupResult::degenerate: ++ch.stats.degenerate; break;
        case SetupResult::outside: ++ch.stats.rejected; break;
      }
      return false;
    };
    auto emit = [&](const WindowVertex* w[3], const V* var[3]) {
      TriangleSetup t;
      if (!count(setup_triangle(*w[0], *w[1], *w[2], sp, t))) return;
      if constexpr (kShaded) {
        t.prim |= uint32_t(ch.interp_count);
        ch.interp_count = ch.interps.append(ch.interp_count, make_interp<V>(w, var));
      }
      keep(t);
    };
    // Depth-only draws set up their unclipped triangles eight at a time (setup_batch.h), in the same order.
    const bool batched = !kShaded && nv <= kBatchMaxVertices;
    // The whole draw's vertex arrays, read at the mesh's indices: asked for ahead (see kVertexPrefetch).
    const bool prefetch_vertices = !in_range && !indices.empty();
    const uintptr_t win_at = reinterpret_cast<uintptr_t>(win), codes_at = reinterpret_cast<uintptr_t>(codes);
    SetupBatch batch(sp, win);
    auto take_one = [&](SetupResult r, const auto& t) {
      if (count(r)) keep(t);
    };
    // A whole batch set up in SIMD (depth-only draws): its outcomes counted at once, its visible records binned in
    // lane order, as take_one lane by lane would (see SetupLanes).
    auto take_lanes = [&](const SetupLanes& s) {
      if constexpr (!kShaded) {
        ch.stats.culled += uint64_t(std::popcount(s.culled));
        ch.stats.degenerate += uint64_t(std::popcount(s.degenerate));
        ch.stats.rejected += uint64_t(std::popcount(s.outside));
        ch.stats.setups += uint64_t(std::popcount(s.visible));
        bins.add_lanes(s.record, s.visible, grid);
      }
    };
    const detail::Overloaded take{take_one, take_lanes};
    // Eight triangles at a time where they can be set up in batches: a group of triangles that are each either
    // rejected or inside the view volume goes straight to the batch; any other group (one to clip, an index out
    // of range) goes through the loop below one triangle at a time.
    size_t one_by_one_until = 0;
    for (size_t i = c * chunk_tris; i < end; ++i) {
      if constexpr (!kShaded) {
        if (batched && i >= one_by_one_until && end - i >= 8) {
          if (prefetch_vertices && end - i >= detail::kVertexPrefetch + 8) {
            // Integer addresses: an index not yet checked against nv may point anywhere.
            const uint32_t* ahead = indices.data() + 3 * (i + detail::kVertexPrefetch);
            for (int k = 0; k < 24; ++k) {
              const uintptr_t v = ahead[k] - base;
              detail::prefetch_address(win_at + v * sizeof(WindowVertex));
              detail::prefetch_address(codes_at + v * sizeof(unsigned));
            }
          }
          TriangleGroup g;
          if (assemble_group(indices, i, codes, base, uint32_t(nv), !in_range, detail::kInvalidVertex, g) &&
              g.clipped == 0) {
            ch.stats.triangles += 8;
            ch.stats.rejected += uint64_t(std::popcount(g.rejected));
            batch.push_lanes(g, g.inside, take);
            i += 7;
            continue;
          }
          one_by_one_until = i + 8;
        }
      }
      uint32_t idx[3];
      for (int k = 0; k < 3; ++k) {
        idx[k] = indices.empty() ? uint32_t(3 * i + k) : indices[3 * i + k];
        if (!in_range && idx[k] >= nv)
          throw DrawError("index " + std::to_string(idx[k]) + " at position " + std::to_string(3 * i + k) +
                          " is out of range (" + std::to_string(nv) + " vertices)");
      }
      ++ch.stats.triangles;
      const unsigned c0 = codes[idx[0] - base], c1 = codes[idx[1] - base], c2 = codes[idx[2] - base];
      if ((c0 & c1 & c2) != 0 || ((c0 | c1 | c2) & detail::kInvalidVertex)) {
        ++ch.stats.rejected;
        continue;
      }
      if ((c0 | c1 | c2) == 0) {
        if (batched) {
          batch.push(idx[0] - base, idx[1] - base, idx[2] - base, take);
          continue;
        }
        const WindowVertex* w[3] = {&win[idx[0] - base], &win[idx[1] - base], &win[idx[2] - base]};
        const V* var[3] = {&post[idx[0]].var, &post[idx[1]].var, &post[idx[2]].var};
        emit(w, var);
        continue;
      }
      batch.flush(take);  // what was queued before this triangle goes first
      ++ch.stats.clipped;
      std::array<CV, 12> poly;
      std::array<WindowVertex, 12> pw;
      CV in[3];
      for (int k = 0; k < 3; ++k) {
        if constexpr (kShaded) in[k] = post[idx[k]];
        else in[k].pos = shader.vertex(vertices[idx[k]], in[k].var);
      }
      const int n = clip_to_window(planes, c0 | c1 | c2, sp, poly, pw, in[0], in[1], in[2]);
      if (n < 3) {
        ++ch.stats.rejected;
        continue;
      }
      for (int k = 1; k + 1 < n; ++k) {
        const auto f = clip_fan(k);  // llvmpipe's fan order: (p[k], p[k+1], p[0])
        const WindowVertex* w[3] = {&pw[f[0]], &pw[f[1]], &pw[f[2]]};
        const V* var[3] = {&poly[f[0]].var, &poly[f[1]].var, &poly[f[2]].var};
        emit(w, var);
      }
    }
    batch.flush(take);
    bins.bin(grid, stream_bins);
  };
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
        Chunk& ch = *chunks_[c];
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
          Chunk& ch = *chunks_[c];
          WorkerScratch& ws = *workers_[size_t(w)];
          const uint32_t lo = ch.range_lo, hi = ch.range_hi;
          unsigned* codes = ws.codes.get<unsigned>(hi - lo + 1);
          WindowVertex* win = ws.win.get<WindowVertex>(hi - lo + 1);
          shade_vertices(lo, size_t(hi) + 1, codes, win);
          front(c, ws, codes, win, lo, true);
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
      timed(front_busy_ns, [&] { front(c, *workers_[size_t(w)], all_codes, all_win, 0, false); });
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
  const std::span<const std::unique_ptr<Chunk>> chunks(chunks_.data(), nchunks);
  for (const auto& ch : chunks) stats += ch->stats;
  const int tx0 = sp.clip.x0 >> kTileSizeLog2, tx1 = sp.clip.x1 >> kTileSizeLog2;
  const int ty0 = sp.clip.y0 >> kTileSizeLog2, ty1 = sp.clip.y1 >> kTileSizeLog2;
  const int ntx = tx1 - tx0 + 1, nty = ty1 - ty0 + 1;
  const bool test = state.depth_test && targets.depth;
  const DepthFunc func = test ? state.depth_func : DepthFunc::always;
  const bool depth_write = test && state.depth_write && func != DepthFunc::never;  // NEVER writes nothing

  // One back end per depth format; the depth function is a run-time DepthCompare for shaded draws and, apart
  // from LESS and LEQUAL, for depth-only draws (dispatch_depth_only_func).
  dispatch_depth_format(format, [&]<DepthFormat F>() {
    auto run_tiles = [&](auto make_stage, bool use_hiz = false) {
      tiles_ran = true;
      // With a clear pending, the tasks cover every tile of the target; otherwise the draw's rectangle's.
      const int gx0 = clear_raw ? 0 : tx0, gy0 = clear_raw ? 0 : ty0;
      const int gnx = clear_raw ? grid.tiles_x : ntx, gny = clear_raw ? grid.tiles_y : nty;
      auto run_tile = [&](size_t k) {
        const int tx = gx0 + int(k % size_t(gnx)), ty = gy0 + int(k / size_t(gnx));
        if (clear_raw) {
          clear_tile(tx, ty);
          if (tx < tx0 || tx > tx1 || ty < ty0 || ty > ty1) return;
        }
        const PixelRect rect{std::max(sp.clip.x0, tx << kTileSizeLog2), std::max(sp.clip.y0, ty << kTileSizeLog2),
                             std::min(sp.clip.x1, ((tx + 1) << kTileSizeLog2) - 1),
                             std::min(sp.clip.y1, ((ty + 1) << kTileSizeLog2) - 1)};
        const size_t tile = size_t(ty) * size_t(grid.tiles_x) + size_t(tx);
        uint32_t records = 0;
        for (const auto& chp : chunks) {
          const auto& offsets = bins_of(*chp).offsets;
          records += offsets[tile + 1] - offsets[tile];
        }
        if (records == 0) return;
        detail::NextTileRows next;  // the lines of the tile this worker likely clears next (see NextTileRows)
        if (clear_raw && k + 1 < size_t(gnx) * size_t(gny)) {
          const int nx = gx0 + int((k + 1) % size_t(gnx)), ny = gy0 + int((k + 1) / size_t(gnx));
          const size_t bpt = targets.depth->bytes_per_texel();
          next.pitch = size_t(targets.depth->pitch()) * bpt;
          next.at = reinterpret_cast<uintptr_t>(targets.depth->template row<uint8_t>(0)) +
                    size_t(ny << kTileSizeLog2) * next.pitch + size_t(nx << kTileSizeLog2) * bpt;
          // A tile of the rightmost column also clears the rest of its rows (fill_tile): the pitch's extra line.
          const bool last = (nx << kTileSizeLog2) + kTileSize >= targets.depth->width();
          const size_t row_bytes = last ? next.pitch - size_t(nx << kTileSizeLog2) * bpt : size_t(kTileSize) * bpt;
          next.lines = int((row_bytes + 63) / 64);
          next.left = kTileSize;
          next.per_record = int(std::min<uint32_t>(kTileSize, (kTileSize + records - 1) / records));
        }
        TileHiZ hiz;  // hierarchical depth, for the stages that use it
        if (use_hiz && clear_raw) hiz.set_all(tx << kTileSizeLog2, ty << kTileSizeLog2, std::bit_cast<float>(*clear_raw));
        else if (use_hiz) hiz.load(*targets.depth, tx << kTileSizeLog2, ty << kTileSizeLog2);
        for (const auto& chp : chunks) {
          const Chunk& ch = *chp;
          const auto stage = make_stage(ch, hiz);
          const ChunkBins<Record>& bins = bins_of(ch);
          const uint32_t b = bins.offsets[tile], e = bins.offsets[tile + 1];
          auto record = [&](uint32_t i) [[gnu::always_inline]] {
            // The record kBinPrefetch ahead is asked for now (see kBinPrefetch), past the slice's end too.
            detail::prefetch_address(reinterpret_cast<uintptr_t>(bins.binned.data() + i) +
                                     detail::kBinPrefetch * sizeof(Record));
            const Record& t = bins.binned[i];
            if constexpr (kShaded) rasterize(t, rect, stage);
            else if (t.full == kNoFullSetup) rasterize(t, rect, stage);
            else rasterize(ch.full.template view<TriangleSetup>()[t.full], rect, stage);
          };
          uint32_t i = b;
          for (; i < e && next.left > 0; ++i) {
            next.ask_rows();
            record(i);
          }
          for (; i < e; ++i) record(i);
        }
      };
      pool_.parallel_for(size_t(gnx) * size_t(gny), [&](size_t k) { timed(back_busy_ns, [&] { run_tile(k); }); });
    };
    if constexpr (kShaded) {
      const DepthCompare compare(func);
      run_tiles([&](const Chunk& ch, TileHiZ&) {
        return ShadedStage<Shader, F>{&shader,      ch.interps.view<TriangleInterp<V>>(),
                                      test ? targets.depth : nullptr, targets.color, compare, depth_write,
                                      state.color_write, state.blend};
      });
    } else if (targets.depth && test) {
      dispatch_depth_only_func(func, [&]<class Compare>(Compare compare) {
        auto depth_only = [&]<bool kWrite>() {
          using Stage = DepthOnlyStage<F, Compare, kWrite>;
          run_tiles([&](const Chunk&, TileHiZ& hiz) { return Stage{targets.depth, &hiz, compare}; }, Stage::kHiZ);
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
