// The pipeline's entry point: a Renderer owns the worker pool and per-draw scratch, and draw<Shader>() runs one
// indexed triangle draw through the stages — vertex shading, primitive assembly + clipping + setup + binning
// (front end, in chunks), then tile execution (back end, one tile per task). Every stage is deterministic.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/bins.h"
#include "raster/clip.h"
#include "raster/coverage.h"
#include "raster/depth_stage.h"
#include "raster/draw_stats.h"
#include "raster/fragment_stage.h"
#include "raster/hiz.h"
#include "raster/interpolation.h"
#include "raster/outcode.h"
#include "raster/scratch.h"
#include "raster/setup.h"
#include "raster/setup_batch.h"
#include "raster/shader.h"
#include "raster/state.h"
#include "raster/target.h"
#include "raster/thread_pool.h"

namespace raster {

// What a draw renders into. Either may be null; when both are set they must have the same size.
struct RenderTargets {
  DepthTarget* depth = nullptr;
  ColorTarget* color = nullptr;
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

  // Draws an indexed triangle list (three indices per triangle); `indices` empty means non-indexed
  // (vertices 3i, 3i+1, 3i+2). The shader is copied once per draw (the snapshot), as is the state.
  template <VertexShader Shader>
  DrawStats draw(RenderTargets targets, const DrawState& state, const Shader& shader,
                 std::span<const typename Shader::Vertex> vertices, std::span<const uint32_t> indices = {});

 private:
  // The front end's output for one chunk of consecutive triangles.
  struct Chunk {
    ChunkBins bins;
    ScratchBuffer interps;  // TriangleInterp<Varyings>, shaded draws only
    size_t interp_count = 0;
    DrawStats stats;
  };

  ThreadPool pool_;
  ScratchBuffer post_, win_, codes_;
  std::vector<std::unique_ptr<Chunk>> chunks_;
};

namespace detail {

inline constexpr size_t kVertexBatch = 8192;
inline constexpr size_t kChunkTriangles = 8192;
inline constexpr unsigned kInvalidVertex = 1u << 31;

void check_draw(const RenderTargets& t, const DrawState& s, size_t vertices, size_t indices);

}  // namespace detail

template <VertexShader Shader>
DrawStats Renderer::draw(RenderTargets targets, const DrawState& state_in, const Shader& shader_in,
                         std::span<const typename Shader::Vertex> vertices, std::span<const uint32_t> indices) {
  using V = typename Shader::Varyings;
  using CV = ClipVertex<V>;
  constexpr bool kShaded = HasFragmentStage<Shader>;

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
  if (ntri == 0 || sp.clip.empty()) return DrawStats{.triangles = ntri, .rejected = ntri};

  // ---- Vertex stage: the shader once per vertex, then outcodes and (for unclipped vertices) window space.
  CV* post = post_.get<CV>(nv);
  WindowVertex* win = win_.get<WindowVertex>(nv);
  unsigned* codes = codes_.get<unsigned>(nv);
  const OutcodeTester outcode_of(planes);
  pool_.parallel_for((nv + detail::kVertexBatch - 1) / detail::kVertexBatch, [&](size_t b) {
    const size_t end = std::min(nv, (b + 1) * detail::kVertexBatch);
    for (size_t i = b * detail::kVertexBatch; i < end; ++i) {
      CV& cv = post[i];
      cv.pos = shader.vertex(vertices[i], cv.var);
      const glm::vec4& p = cv.pos;
      const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
      codes[i] = finite ? outcode_of(p) : detail::kInvalidVertex;
      if (codes[i] == 0) win[i] = to_window(p, sp);
    }
  });

  // ---- Front end: assembly, clipping, setup, binning, in chunks of consecutive triangles.
  const TileGrid grid = TileGrid::for_size(width, height);
  const size_t nchunks = (ntri + detail::kChunkTriangles - 1) / detail::kChunkTriangles;
  while (chunks_.size() < nchunks) chunks_.push_back(std::make_unique<Chunk>());
  pool_.parallel_for(nchunks, [&](size_t c) {
    Chunk& ch = *chunks_[c];
    ch.bins.reset(grid);
    ch.interp_count = 0;
    ch.stats = DrawStats{};
    const size_t end = std::min(ntri, (c + 1) * detail::kChunkTriangles);
    ch.bins.setups.reserve(end - c * detail::kChunkTriangles);
    auto emit = [&](const WindowVertex* w[3], const V* var[3]) {
      TriangleSetup t;
      switch (setup_triangle(*w[0], *w[1], *w[2], sp, t)) {
        case SetupResult::visible: break;
        case SetupResult::culled: ++ch.stats.culled; return;
        case SetupResult::degenerate: ++ch.stats.degenerate; return;
        case SetupResult::outside: ++ch.stats.rejected; return;
      }
      if constexpr (kShaded) {
        t.prim |= uint32_t(ch.interp_count);
        ch.interp_count = ch.interps.append(ch.interp_count, make_interp<V>(w, var));
      }
      ++ch.stats.setups;
      ch.bins.add(t, grid);
    };
    // Depth-only draws set up their unclipped triangles eight at a time (setup_batch.h), in the same order.
    const bool batched = !kShaded && nv <= kBatchMaxVertices;
    SetupBatch batch(sp, win);
    auto take = [&](SetupResult r, const TriangleSetup& t) {
      switch (r) {
        case SetupResult::visible: break;
        case SetupResult::culled: ++ch.stats.culled; return;
        case SetupResult::degenerate: ++ch.stats.degenerate; return;
        case SetupResult::outside: ++ch.stats.rejected; return;
      }
      ++ch.stats.setups;
      ch.bins.add(t, grid);
    };
    for (size_t i = c * detail::kChunkTriangles; i < end; ++i) {
      uint32_t idx[3];
      for (int k = 0; k < 3; ++k) {
        idx[k] = indices.empty() ? uint32_t(3 * i + k) : indices[3 * i + k];
        if (idx[k] >= nv)
          throw DrawError("index " + std::to_string(idx[k]) + " at position " + std::to_string(3 * i + k) +
                          " is out of range (" + std::to_string(nv) + " vertices)");
      }
      ++ch.stats.triangles;
      const unsigned c0 = codes[idx[0]], c1 = codes[idx[1]], c2 = codes[idx[2]];
      if ((c0 & c1 & c2) != 0 || ((c0 | c1 | c2) & detail::kInvalidVertex)) {
        ++ch.stats.rejected;
        continue;
      }
      if ((c0 | c1 | c2) == 0) {
        if (batched) {
          batch.push(idx[0], idx[1], idx[2], take);
          continue;
        }
        const WindowVertex* w[3] = {&win[idx[0]], &win[idx[1]], &win[idx[2]]};
        const V* var[3] = {&post[idx[0]].var, &post[idx[1]].var, &post[idx[2]].var};
        emit(w, var);
        continue;
      }
      batch.flush(take);  // what was queued before this triangle goes first
      ++ch.stats.clipped;
      std::array<CV, 12> poly;
      std::array<WindowVertex, 12> pw;
      const int n = clip_to_window(planes, c0 | c1 | c2, sp, poly, pw, post[idx[0]], post[idx[1]], post[idx[2]]);
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
    ch.bins.bin(grid);
  });

  // ---- Back end: each tile executes its commands, chunk by chunk, in submission order.
  DrawStats stats;
  const std::span<const std::unique_ptr<Chunk>> chunks(chunks_.data(), nchunks);
  for (const auto& ch : chunks) stats += ch->stats;
  const int tx0 = sp.clip.x0 >> kTileSizeLog2, tx1 = sp.clip.x1 >> kTileSizeLog2;
  const int ty0 = sp.clip.y0 >> kTileSizeLog2, ty1 = sp.clip.y1 >> kTileSizeLog2;
  const int ntx = tx1 - tx0 + 1, nty = ty1 - ty0 + 1;
  const bool test = state.depth_test && targets.depth;
  const DepthFunc func = test ? state.depth_func : DepthFunc::always;
  const bool depth_write = test && state.depth_write;

  dispatch_depth_format(format, [&]<DepthFormat F>() {
    dispatch_depth_func(func, [&]<DepthFunc Func>() {
      auto run_tiles = [&](auto make_stage, bool use_hiz = false) {
        pool_.parallel_for(size_t(ntx) * size_t(nty), [&](size_t k) {
          const int tx = tx0 + int(k % size_t(ntx)), ty = ty0 + int(k / size_t(ntx));
          const PixelRect rect{std::max(sp.clip.x0, tx << kTileSizeLog2), std::max(sp.clip.y0, ty << kTileSizeLog2),
                               std::min(sp.clip.x1, ((tx + 1) << kTileSizeLog2) - 1),
                               std::min(sp.clip.y1, ((ty + 1) << kTileSizeLog2) - 1)};
          const size_t tile = size_t(ty) * size_t(grid.tiles_x) + size_t(tx);
          bool any = false;
          for (const auto& chp : chunks) any |= chp->bins.offsets[tile] != chp->bins.offsets[tile + 1];
          if (!any) return;
          TileHiZ hiz;  // hierarchical depth, for the stages that use it
          if (use_hiz) hiz.load(*targets.depth, tx << kTileSizeLog2, ty << kTileSizeLog2);
          for (const auto& chp : chunks) {
            const Chunk& ch = *chp;
            const auto stage = make_stage(ch, hiz);
            const uint32_t b = ch.bins.offsets[tile], e = ch.bins.offsets[tile + 1];
            for (uint32_t i = b; i < e; ++i) {
              const TriangleSetup& t = ch.bins.binned[i];
              rasterize(t, rect, stage);
            }
          }
        });
      };
      if constexpr (kShaded) {
        run_tiles([&](const Chunk& ch, TileHiZ&) {
          return ShadedStage<Shader, F, Func>{&shader, ch.interps.view<TriangleInterp<V>>(), test ? targets.depth : nullptr,
                                               targets.color, depth_write, state.color_write, state.blend};
        });
      } else if (targets.depth && test) {
        auto depth_only = [&]<bool kWrite>() {
          using Stage = DepthOnlyStage<F, Func, kWrite>;
          run_tiles([&](const Chunk&, TileHiZ& hiz) { return Stage{targets.depth, &hiz}; }, Stage::kHiZ);
        };
        if (depth_write) depth_only.template operator()<true>();
        else depth_only.template operator()<false>();
      }
    });
  });
  return stats;
}

}  // namespace raster
