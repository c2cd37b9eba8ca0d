// The front end of one chunk of a draw's consecutive triangles: primitive assembly, clipping, triangle set-up
// (eight triangles at a time where they need no clipping, in depth-only draws) and binning into the chunk's
// per-tile slices (BinnedChunk). Renderer::draw runs one chunk per task, after or inside the vertex stage.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "raster/assembly.h"
#include "raster/binned_chunk.h"
#include "raster/bins.h"
#include "raster/clip.h"
#include "raster/depth_setup.h"
#include "raster/interpolation.h"
#include "raster/prefetch.h"
#include "raster/primitive.h"
#include "raster/setup.h"
#include "raster/setup_batch.h"
#include "raster/shader.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Invalid draw input (an index out of range, mismatched targets, a bad viewport). The message says which.
struct DrawError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

namespace detail {

// One callable made of several lambdas, each serving the calls its parameters take.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // spelled out: clang 14 (the fuzzers' compiler) deduces no aggregate

// The outcode bit the vertex stage sets on a vertex it could not place (VertexBatch): triangles using it are
// dropped.
inline constexpr unsigned kInvalidVertex = 1u << 31;

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

}  // namespace detail

// One chunk's front end, for the draws of one shader: the draw's snapshot (shader, state turned into set-up
// parameters and clip planes), its inputs and how it is split into chunks.
template <VertexShader Shader>
struct ChunkFrontEnd {
  using V = typename Shader::Varyings;
  using CV = ClipVertex<V>;
  static constexpr bool kShaded = HasFragmentStage<Shader>;
  using Record = std::conditional_t<kShaded, TriangleSetup, DepthSetup>;  // what bins carry (BinnedChunk)

  const Shader& shader;
  std::span<const typename Shader::Vertex> vertices;
  std::span<const uint32_t> indices;  // empty: non-indexed
  const SetupParams& sp;
  const ClipPlanes& planes;
  const CV* post;  // shaded draws: every vertex's clip-space position and varyings (null in depth-only draws)
  TileGrid grid;
  size_t ntri, chunk_tris;  // the draw's triangles, and per chunk
  bool stream_bins;         // bin with non-temporal stores (ChunkBins::bin)

  // Chunk c's front end into `ch`, its records staged in `staging` (the worker's), reading vertex i's outcode and
  // window position at codes[i − base], win[i − base]. `in_range`: the chunk's indices are known to be below the
  // vertex count (its range was measured), so none is tested again; otherwise an index out of range throws a
  // DrawError naming it.
  void operator()(size_t c, BinnedChunk& ch, Staging<Record>& staging, const unsigned* codes,
                  const WindowVertex* win, uint32_t base, bool in_range) const {
    ChunkBins<Record>& bins = ch.bins<Record>();
    const size_t nv = vertices.size();
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
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
