// Primitive assembly eight triangles at a time (raster/assembly.h): each lane's vertex offsets and its outcome
// (rejected, inside, to clip) are the one-triangle rule's, for indexed and non-indexed draws, with a base offset,
// invalid vertices and indices out of range; and depth-only draws, whose front end takes such groups and sets their
// triangles up in batches, count and draw exactly as shaded draws of the same triangles, whose front end goes one
// triangle at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "bench/triangle_soup.h"
#include "raster/assembly.h"
#include "tests/raster/raster_test_util.h"

using namespace raster;

namespace {

constexpr unsigned kInvalid = 1u << 31;

// The front end's rule for one triangle (renderer.h).
enum class Outcome { rejected, inside, clipped };
Outcome one_triangle(unsigned c0, unsigned c1, unsigned c2) {
  if ((c0 & c1 & c2) != 0 || ((c0 | c1 | c2) & kInvalid)) return Outcome::rejected;
  return (c0 | c1 | c2) == 0 ? Outcome::inside : Outcome::clipped;
}

}  // namespace

TEST(Assembly, GroupsFollowTheOneTriangleRule) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, 15);
  int taken = 0, refused = 0, seen[3] = {0, 0, 0};
  for (int round = 0; round < 4000; ++round) {
    const bool indexed = round % 3 != 0, check = round % 2 == 0;
    const size_t first = rng() % 40;
    // A soup's chunk reads the outcodes of its own vertices, from its first one on: base ≤ 3 · first.
    const uint32_t base = indexed ? (round % 5 == 0 ? 0u : uint32_t(rng() % 1000)) : uint32_t(rng() % (3 * first + 1));
    const uint32_t nv = base + 200;
    // Outcodes of vertices base … nv − 1: mostly inside, some outside one or two planes, a few invalid.
    std::vector<unsigned> codes(nv - base);
    for (unsigned& c : codes) {
      const int p = pick(rng);
      c = p < 9 ? 0u : p < 15 ? (1u << (p % 6)) | (p == 14 ? 1u << ((p + 1) % 6) : 0u) : kInvalid;
    }
    std::vector<uint32_t> indices;
    if (indexed) {
      indices.resize(3 * (first + 8));
      for (uint32_t& i : indices) i = base + uint32_t(rng() % (nv - base));
      if (round % 7 == 0) indices[3 * first + rng() % 24] = rng() % 2 ? nv : ~0u;  // out of range
    }
    const bool out_of_range = indexed && round % 7 == 0;
    if (out_of_range && !check) continue;                           // callers check whenever ranges are unknown
    TriangleGroup g;
    const bool ok = assemble_group(indices, first, codes.data(), base, nv, check, kInvalid, g);
    ASSERT_EQ(ok, !(out_of_range && check)) << "round " << round;
    if (!ok) {
      ++refused;
      continue;
    }
    ++taken;
    EXPECT_EQ(g.rejected | g.inside | g.clipped, 0xFFu);
    EXPECT_EQ(g.rejected & g.inside, 0u);
    EXPECT_EQ((g.rejected | g.inside) & g.clipped, 0u);
    for (int l = 0; l < 8; ++l) {
      unsigned c[3];
      for (int k = 0; k < 3; ++k) {
        const size_t at = 3 * (first + size_t(l)) + size_t(k);
        const uint32_t index = indexed ? indices[at] : uint32_t(at);
        ASSERT_EQ(g.vertex[k][l], int32_t(index - base)) << "round " << round << " lane " << l << " vertex " << k;
        c[k] = codes[index - base];
      }
      const Outcome want = one_triangle(c[0], c[1], c[2]);
      const Outcome got = g.rejected >> l & 1u ? Outcome::rejected : g.inside >> l & 1u ? Outcome::inside : Outcome::clipped;
      EXPECT_EQ(got, want) << "round " << round << " lane " << l;
      ++seen[int(want)];
    }
  }
  // Every outcome and both answers occurred often enough to mean something.
  EXPECT_GT(taken, 1000);
  EXPECT_GT(refused, 50);
  for (int n : seen) EXPECT_GT(n, 1000);
}

// Triangles in runs: long runs inside the view volume (whole groups set up in batches), and runs that mix
// triangles inside, outside one plane (rejected), across a plane (clipped: sides and near plane) and with a NaN
// vertex (rejected). Depth-only draws must report the same counts as shaded draws and leave the same buffer,
// indexed over a shared vertex pool and as a soup, at 0 and 3 threads; with ALWAYS, where the last triangle
// drawn at a pixel wins, the buffer shows the order they were set up in too.
TEST(Assembly, DepthOnlyDrawsCountAndDrawAsShadedDraws) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.9f, 0.9f), far_x(1.2f, 2.0f), zq(-0.9f, 0.9f);
  std::vector<glm::vec4> pool;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto vertex = [&](int kind) {  // 0 inside, 1 right of the volume, 2 NaN, 3 in front of the near plane
    glm::vec4 p(u(rng), u(rng), zq(rng), 1.0f);
    if (kind == 1) p.x = far_x(rng);
    if (kind == 2) p.y = nan;
    if (kind == 3) p.z = -1.5f;
    pool.push_back(p);
    return uint32_t(pool.size() - 1);
  };
  std::vector<uint32_t> indices, inside;
  auto triangle = [&](int a, int b, int c) {
    for (int kind : {a, b, c}) {
      if (kind == 0 && inside.size() > 8 && rng() % 3 == 0) {  // shared with an earlier triangle, as in meshes
        indices.push_back(inside[rng() % inside.size()]);
        continue;
      }
      indices.push_back(vertex(kind));
      if (kind == 0) inside.push_back(indices.back());
    }
  };
  for (int run = 0; run < 400; ++run) {
    const int n = 1 + int(rng() % 24);
    const bool mixed = run % 2 == 1;
    for (int t = 0; t < n; ++t) {
      const int kind = mixed ? int(rng() % 5) : 0;
      if (kind == 0) triangle(0, 0, 0);
      if (kind == 1) triangle(1, 1, 1);  // rejected
      if (kind == 2) triangle(0, 0, 1);  // clipped against x = w
      if (kind == 3) triangle(0, 2, 0);  // a NaN vertex: rejected
      if (kind == 4) triangle(0, 3, 0);  // clipped against the near plane
    }
  }
  std::vector<glm::vec4> soup;
  for (uint32_t i : indices) soup.push_back(pool[i]);
  const int W = 300, H = 200;
  for (int threads : {0, 3}) {
    for (DepthFunc func : {DepthFunc::less, DepthFunc::always}) {
      Renderer r(threads);
      DrawState state;
      state.depth_func = func;
      for (const bool indexed : {true, false}) {
        const std::span<const glm::vec4> pos = indexed ? std::span<const glm::vec4>(pool) : std::span<const glm::vec4>(soup);
        const std::span<const uint32_t> idx = indexed ? std::span<const uint32_t>(indices) : std::span<const uint32_t>();
        DepthTarget fast(W, H, DepthFormat::d32f), slow(W, H, DepthFormat::d32f);
        ColorTarget color(W, H, ColorFormat::rgba8);
        const DrawStats a = r.draw(RenderTargets{&fast}, state, ClipSpaceDepthShader{}, pos, idx);
        const DrawStats b = r.draw(RenderTargets{&slow, &color}, state, rtest::WhiteShader{}, pos, idx);
        const std::string what = std::string(indexed ? "indexed" : "soup") + ", " + std::to_string(threads) +
                                 " threads, " + (func == DepthFunc::less ? "LESS" : "ALWAYS");
        EXPECT_EQ(a.triangles, indices.size() / 3) << what;
        EXPECT_EQ(a.triangles, b.triangles) << what;
        EXPECT_EQ(a.clipped, b.clipped) << what;
        EXPECT_EQ(a.rejected, b.rejected) << what;
        EXPECT_EQ(a.culled, b.culled) << what;
        EXPECT_EQ(a.degenerate, b.degenerate) << what;
        EXPECT_EQ(a.setups, b.setups) << what;
        EXPECT_GT(a.clipped, 200u) << what;
        EXPECT_GT(a.rejected, 400u) << what;
        EXPECT_GT(a.setups, a.triangles / 2) << what;
        EXPECT_EQ(rtest::hash_depth(fast), rtest::hash_depth(slow)) << what;
      }
    }
  }
}

// The setup outcomes of a depth-only draw's batches (raster/setup_batch.h), which its front end counts a batch at a
// time (SetupLanes), against a shaded draw's one triangle at a time: tiny triangles, many of them between pixel
// centres (outside), some with two vertices snapped together (degenerate), and back faces culled.
TEST(Assembly, DepthOnlyBatchesCountSetupOutcomesAsShadedDraws) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> centre(-0.95f, 0.95f), off(-0.012f, 0.012f), depth(0.0f, 0.9f);
  std::vector<glm::vec4> soup;
  for (int t = 0; t < 20000; ++t) {
    const float cx = centre(rng), cy = centre(rng);
    glm::vec4 p[3];
    for (auto& q : p) q = glm::vec4(cx + off(rng), cy + off(rng), depth(rng), 1.0f);
    if (t % 9 == 0) p[2] = p[1];  // degenerate
    soup.insert(soup.end(), p, p + 3);
  }
  const int W = 256, H = 192;  // triangles of up to ~3 pixels
  for (int threads : {0, 2}) {
    Renderer r(threads);
    DrawState state;
    state.cull = CullMode::back;
    DepthTarget fast(W, H, DepthFormat::d32f), slow(W, H, DepthFormat::d32f);
    ColorTarget color(W, H, ColorFormat::rgba8);
    const DrawStats a = r.draw(RenderTargets{&fast}, state, ClipSpaceDepthShader{}, std::span<const glm::vec4>(soup));
    const DrawStats b = r.draw(RenderTargets{&slow, &color}, state, rtest::WhiteShader{}, std::span<const glm::vec4>(soup));
    const std::string what = std::to_string(threads) + " threads";
    EXPECT_EQ(a.triangles, soup.size() / 3) << what;
    EXPECT_EQ(a.culled, b.culled) << what;
    EXPECT_EQ(a.degenerate, b.degenerate) << what;
    EXPECT_EQ(a.rejected, b.rejected) << what;
    EXPECT_EQ(a.setups, b.setups) << what;
    EXPECT_GT(a.culled, a.triangles / 4) << what;
    EXPECT_GT(a.degenerate, a.triangles / 20) << what;
    EXPECT_GT(a.rejected, a.triangles / 10) << what;  // boxes with no pixel centre
    EXPECT_GT(a.setups, a.triangles / 10) << what;
    EXPECT_EQ(rtest::hash_depth(fast), rtest::hash_depth(slow)) << what;
  }
}

// A depth-only mesh draw measures its chunks' vertex ranges to choose between shading each chunk's own range and
// shading every vertex once (renderer.h), and stops measuring at the first chunk whose range is not compact. The
// chunks it skipped still hold the ranges of the renderer's previous draw, which must not be used: here a soup
// drawn first leaves compact ranges on every chunk, then a mesh over the same vertices whose first chunk reaches a
// little too far (alone it would still pass the total) and whose other chunks read each other's vertices. Inline
// (0 threads) the chunks run in order, so the later ones are skipped every time. Same bits as a shaded draw of the
// mesh, and as the mesh drawn by a renderer with no previous draw.
TEST(Assembly, MeshDrawsAfterASoupUseNoStaleVertexRanges) {
  constexpr uint32_t kTris = 8000, kChunk = 2000;  // 0 threads: four chunks of 2000 triangles (renderer.h)
  ASSERT_EQ(detail::chunk_triangles(kTris, 1), kChunk);
  const auto soup = bench::make_soup(kTris, 30.0, 256, 7);
  std::vector<uint32_t> mesh(3 * kTris);
  for (uint32_t t = 0; t < kTris; ++t) {
    const uint32_t chunk = t / kChunk;
    uint32_t from = t;                                                // chunk 0 reads its own triangles' vertices
    if (chunk == 1 || chunk == 3) from = (4 - chunk) * kChunk + t % kChunk;  // chunks 1 and 3 swap theirs
    if (t == kChunk - 1) from = kChunk + 300;                         // chunk 0's last reaches into chunk 1's
    for (uint32_t k = 0; k < 3; ++k) mesh[3 * t + k] = 3 * from + k;
  }
  const std::span<const glm::vec4> pos(soup.positions);
  auto depth_only = [&](Renderer& r, std::span<const uint32_t> idx) {
    DepthTarget d(256, 256, DepthFormat::d32f);
    d.clear(1.0f);
    r.draw(RenderTargets{&d}, DrawState{}, ClipSpaceDepthShader{}, pos, idx);
    return rtest::hash_depth(d);
  };
  Renderer fresh(0), shaded(0);
  DepthTarget d(256, 256, DepthFormat::d32f);
  ColorTarget color(256, 256, ColorFormat::rgba8);
  d.clear(1.0f);
  shaded.draw(RenderTargets{&d, &color}, DrawState{}, rtest::WhiteShader{}, pos, std::span<const uint32_t>(mesh));
  const uint64_t expected = rtest::hash_depth(d);
  EXPECT_EQ(depth_only(fresh, mesh), expected);
  for (int threads : {0, 1, 2}) {
    Renderer r(threads);
    const uint64_t soup_hash = depth_only(r, {});  // non-indexed: every chunk's range compact
    EXPECT_NE(soup_hash, expected) << threads;     // the mesh draws other triangles than the soup
    EXPECT_EQ(depth_only(r, mesh), expected) << threads << " threads";
    EXPECT_EQ(depth_only(r, {}), soup_hash) << threads << " threads";
  }
}
