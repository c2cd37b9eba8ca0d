// The eight- and sixteen-lane PCF kernels (pcf_lequal_x8 and pcf_lequal_x16, PcfKernel's SIMD forms, what
// fragment_pair shaders and the multi-tap filters call) equal the scalar kernel lane by lane, bit for bit: every
// fast-path format and wrap, textures as views of padded targets and as tightly packed storage, sizes down to
// one texel, coordinates inside, on texel centres, on and beyond every edge and corner, and non-finite; groups
// wholly inside the map (the kernels' short paths) and groups with a single lane outside it, in every lane
// position of sixteen; groups of eight neighbouring footprints (the sixteen-lane window path) up to and one texel
// past the window's 8 × 4 texels and the map's last column and row; and several sixteen-lane lookups handed over
// at once (PcfKernel's batch form, pcf_lequal_x16_n), some of them leaving the window path; maps that end where
// an unreadable page begins, so that any read past the last texel faults; and rows 2^15 texels apart or more.
// The test binary is built for the first instruction set of SHADOWLAB_ISAS: the sixteen-lane kernel's AVX-512
// form (and the batch's) is what a build configured with SHADOWLAB_ISAS=avx512 tests, on a CPU that has it.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <initializer_list>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "raster/simd/vec.h"
#include "raster/target.h"
#include "shading/shadow_lookup.h"

namespace {

using raster::simd::VecF32;
using raster::simd::VecF32x16;
using shading::TexelFormat;
using shading::Texture2D;

constexpr float kBorder = 0.75f;

// N sixteen-lane lookups at once (the batch form), lane by lane against the scalar kernel.
template <TexelFormat F, bool kBorderWrap, size_t N>
void expect_batches_match(const shading::PcfKernel<F, kBorderWrap>& kernel, const shading::TextureLevel& L,
                          const std::vector<glm::vec3>& pts, const char* what) {
  for (size_t k = 0; k + 16 * N <= pts.size(); k += 16 * N) {
    std::array<VecF32x16, N> s, t, r, out;
    for (size_t n = 0; n < N; ++n) {
      alignas(64) float ps[16], pt[16], pr[16];
      for (size_t l = 0; l < 16; ++l) {
        const glm::vec3 p = pts[k + 16 * n + l];
        ps[l] = p.x, pt[l] = p.y, pr[l] = p.z;
      }
      s[n] = VecF32x16::load_rows(ps, ps + 8), t[n] = VecF32x16::load_rows(pt, pt + 8);
      r[n] = VecF32x16::load_rows(pr, pr + 8);
    }
    kernel(s, t, r, out);
    for (size_t n = 0; n < N; ++n) {
      alignas(64) float o[16];
      out[n].store_rows(o, o + 8);
      for (size_t l = 0; l < 16; ++l) {
        const glm::vec3 p = pts[k + 16 * n + l];
        const float scalar = shading::detail::pcf_lequal_scalar<F, kBorderWrap>(L, p, kBorder);
        ASSERT_EQ(std::bit_cast<uint32_t>(o[l]), std::bit_cast<uint32_t>(scalar))
            << what << " batch of " << N << ", lookup " << n << ", lane " << l << ", " << L.width << "x"
            << L.height << (kBorderWrap ? " border" : " edge") << " at (" << p.x << ", " << p.y << ", " << p.z
            << ")";
      }
    }
  }
}

template <TexelFormat F, bool kBorderWrap>
void expect_lanes_match(const shading::TextureLevel& L, const std::vector<glm::vec3>& pts, const char* what) {
  const shading::PcfKernel<F, kBorderWrap> kernel{L, kBorder};
  for (size_t k = 0; k + 8 <= pts.size(); k += 8) {
    alignas(32) float s[8], t[8], r[8], out[8];
    for (int l = 0; l < 8; ++l) s[l] = pts[k + l].x, t[l] = pts[k + l].y, r[l] = pts[k + l].z;
    kernel(VecF32::load(s), VecF32::load(t), VecF32::load(r)).store(out);
    for (int l = 0; l < 8; ++l) {
      const glm::vec3 p = pts[k + l];
      const float scalar = shading::detail::pcf_lequal_scalar<F, kBorderWrap>(L, p, kBorder);
      ASSERT_EQ(std::bit_cast<uint32_t>(out[l]), std::bit_cast<uint32_t>(scalar))
          << what << " " << L.width << "x" << L.height << (kBorderWrap ? " border" : " edge") << " at ("
          << p.x << ", " << p.y << ", " << p.z << ")";
      ASSERT_EQ(std::bit_cast<uint32_t>(kernel(p)), std::bit_cast<uint32_t>(scalar));
    }
  }
  for (size_t k = 0; k + 16 <= pts.size(); k += 16) {
    alignas(64) float s[16], t[16], r[16], out[16];
    for (int l = 0; l < 16; ++l) s[l] = pts[k + l].x, t[l] = pts[k + l].y, r[l] = pts[k + l].z;
    kernel(VecF32x16::load_rows(s, s + 8), VecF32x16::load_rows(t, t + 8), VecF32x16::load_rows(r, r + 8))
        .store_rows(out, out + 8);
    for (int l = 0; l < 16; ++l) {
      const glm::vec3 p = pts[k + l];
      const float scalar = shading::detail::pcf_lequal_scalar<F, kBorderWrap>(L, p, kBorder);
      ASSERT_EQ(std::bit_cast<uint32_t>(out[l]), std::bit_cast<uint32_t>(scalar))
          << what << " sixteen lanes, lane " << l << ", " << L.width << "x" << L.height
          << (kBorderWrap ? " border" : " edge") << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
  }
  expect_batches_match<F, kBorderWrap, 4>(kernel, L, pts, what);
  expect_batches_match<F, kBorderWrap, 3>(kernel, L, pts, what);
}

// Groups of eight lanes with neighbouring footprints, as a fragment pair's eight pixels have: lane l's texel
// indices (i0, j0) = (floor(s · w − 0.5), floor(t · h − 0.5)) lie within spans (kx, ky) of the group's corner
// (x0, y0), lanes 0 and 7 at the ends of the x span and lanes 1 and 6 at those of the y span. Spans up to the
// window's (6, 2) and one past it; corners at 0, anywhere, and at the last ones a window can start at (w − 8,
// h − 4) and one past. Needs w, h >= 2 (footprints inside the map); appends whole groups.
void append_neighbour_groups(int w, int h, std::mt19937& rng, std::vector<glm::vec3>& pts) {
  if (w < 2 || h < 2) return;
  std::uniform_real_distribution<float> frac(0.05f, 0.95f), ref(-0.1f, 1.1f);
  auto pick = [&](std::initializer_list<int> v) {
    return *(v.begin() + std::uniform_int_distribution<size_t>(0, v.size() - 1)(rng));
  };
  auto coord = [&](int i, int n) { return (float(i) + 0.5f + frac(rng)) / float(n); };  // texel index i
  for (int g = 0; g < 600; ++g) {
    const int kx = std::min(pick({0, 3, 6, 6, 7}), w - 2), ky = std::min(pick({0, 1, 2, 2, 3}), h - 2);
    auto corner = [&](int n, int k, int last) {  // last: the last corner a window can start at
      const int c = pick({0, std::uniform_int_distribution<int>(0, n - 2 - k)(rng), last, last, last + 1});
      return std::clamp(c, 0, n - 2 - k);
    };
    const int x0 = corner(w, kx, w - 8), y0 = corner(h, ky, h - 4);
    for (int l = 0; l < 8; ++l) {
      const int dx = l == 0 ? 0 : l == 7 ? kx : std::uniform_int_distribution<int>(0, kx)(rng);
      const int dy = l == 1 ? 0 : l == 6 ? ky : std::uniform_int_distribution<int>(0, ky)(rng);
      pts.emplace_back(coord(x0 + dx, w), coord(y0 + dy, h), ref(rng));
    }
  }
}

// Coordinates for a w×h texture: random ones over and around it, and for every texel boundary and centre on
// both axes (which puts lanes on each edge and corner), plus far-away and non-finite values.
std::vector<glm::vec3> coordinates(int w, int h, std::mt19937& rng) {
  std::uniform_real_distribution<float> coord(-0.3f, 1.3f), ref(-0.1f, 1.1f);
  std::vector<glm::vec3> pts;
  for (int k = 0; k < 4000; ++k) pts.emplace_back(coord(rng), coord(rng), ref(rng));
  std::vector<float> xs, ys;
  for (int i = -1; i <= w + 1; ++i) xs.insert(xs.end(), {float(i) / float(w), (float(i) + 0.5f) / float(w)});
  for (int j = -1; j <= h + 1; ++j) ys.insert(ys.end(), {float(j) / float(h), (float(j) + 0.5f) / float(h)});
  for (float x : xs)
    for (float y : ys) pts.emplace_back(x, y, ref(rng));
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (glm::vec3 q : {glm::vec3(1e9f, -1e9f, 0.5f), glm::vec3(-inf, inf, 0.5f), glm::vec3(nan, 0.5f, 0.5f),
                      glm::vec3(0.5f, nan, 0.5f), glm::vec3(0.5f, 0.5f, nan), glm::vec3(0.3f, 0.7f, 1.5f),
                      glm::vec3(0.3f, 0.7f, -0.5f), glm::vec3(-1e-7f, 1.0f + 1e-7f, 0.5f)})
    pts.push_back(q);
  std::shuffle(pts.begin(), pts.end(), rng);  // mix edge lanes with inside lanes in one call
  while (pts.size() % 16) pts.emplace_back(0.5f, 0.5f, 0.5f);
  // Whole groups inside the map (the kernels' short paths), and groups of fifteen inside lanes with one lane just
  // past an edge, far away or NaN, in every lane position (so each half of eight is, in turn, all inside and one
  // lane out): the short paths' tests must send those to the full ones.
  auto inside = [](int n) {  // s with 0 < s · n − 0.5 < n − 1: footprints inside (none when n < 2)
    const float lo = 0.51f / float(n);
    return std::uniform_real_distribution<float>(lo, std::max(lo, (float(n) - 0.51f) / float(n)));
  };
  auto inside_s = inside(w), inside_t = inside(h);
  for (int k = 0; k < 800; ++k) pts.emplace_back(inside_s(rng), inside_t(rng), ref(rng));
  const float eps = 1e-4f;
  const glm::vec2 outside[] = {{0.5f / float(w) - eps, 0.5f},      {0.5f, 0.5f / float(h) - eps},
                               {1.0f - 0.5f / float(w) + eps, 0.5f}, {0.5f, 1.0f - 0.5f / float(h) + eps},
                               {3e9f, 0.5f},                        {0.5f, -3e9f},
                               {nan, 0.5f},                         {0.5f, inf}};
  for (glm::vec2 o : outside)
    for (int lane = 0; lane < 16; ++lane)
      for (int l = 0; l < 16; ++l)
        pts.push_back(l == lane ? glm::vec3(o, ref(rng)) : glm::vec3(inside_s(rng), inside_t(rng), ref(rng)));
  append_neighbour_groups(w, h, rng, pts);
  return pts;
}

template <TexelFormat F>
void check_format(const shading::TextureLevel& L, std::mt19937& rng, const char* what) {
  const std::vector<glm::vec3> pts = coordinates(L.width, L.height, rng);
  expect_lanes_match<F, false>(L, pts, what);
  expect_lanes_match<F, true>(L, pts, what);
}
template <TexelFormat F>
void check_format(const Texture2D& tex, std::mt19937& rng, const char* what) {
  check_format<F>(tex.level(0), rng, what);
}

TEST(PcfSimd, EightAndSixteenLanesEqualTheScalarKernelOnTargetViews) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  for (auto [w, h] : {std::pair{37, 23}, {64, 64}, {1, 9}, {9, 1}, {1, 1}, {2, 2}, {65, 3}, {8, 4}}) {
    for (raster::DepthFormat f : {raster::DepthFormat::d16, raster::DepthFormat::d24, raster::DepthFormat::d32f}) {
      raster::DepthTarget target(w, h, f);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const float z = depth(rng);
          if (f == raster::DepthFormat::d16) target.row<uint16_t>(y)[x] = uint16_t(z * 65535.0f);
          if (f == raster::DepthFormat::d24) target.row<uint32_t>(y)[x] = uint32_t(z * 16777215.0f) | 0xAB000000u;
          if (f == raster::DepthFormat::d32f) target.row<float>(y)[x] = z;
        }
      const Texture2D tex = Texture2D::view(target);
      switch (f) {
        case raster::DepthFormat::d16: check_format<TexelFormat::d16>(tex, rng, "d16 view"); break;
        case raster::DepthFormat::d24: check_format<TexelFormat::d24>(tex, rng, "d24 view"); break;
        case raster::DepthFormat::d32f: check_format<TexelFormat::d32f>(tex, rng, "d32f view"); break;
      }
    }
  }
}

// Tightly packed storage (d32f and d16): the comparison in another layout (rows one texel apart).
TEST(PcfSimd, EightAndSixteenLanesEqualTheScalarKernelOnPackedTextures) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  for (auto [w, h] : {std::pair{16, 16}, {5, 7}, {2, 1}, {1, 2}, {8, 4}, {12, 6}}) {
    std::vector<float> z(size_t(w) * h);
    for (float& v : z) v = depth(rng);
    check_format<TexelFormat::d32f>(Texture2D::from_floats(w, h, TexelFormat::d32f, 1, z), rng, "d32f packed");
    check_format<TexelFormat::d16>(Texture2D::from_floats(w, h, TexelFormat::d16, 1, z), rng, "d16 packed");
  }
}

// A w×h map of 2- or 4-byte texels, packed, whose last texel ends where an unreadable page begins (mmap, then
// mprotect): a kernel that reads a byte past the map faults, where a comparison of values could not tell (a
// window one column or row too far loads texels it never picks) and an allocator's rounding would hide it.
class GuardedLevel {
 public:
  GuardedLevel(int w, int h, int texel_bytes) {
    const size_t page = size_t(sysconf(_SC_PAGESIZE)), bytes = size_t(w) * size_t(h) * size_t(texel_bytes);
    size_ = (bytes + page - 1) / page * page + page;
    void* p = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::runtime_error("mmap failed");
    base_ = static_cast<std::byte*>(p);
    if (mprotect(base_ + size_ - page, page, PROT_NONE) != 0) throw std::runtime_error("mprotect failed");
    level_ = {base_ + size_ - page - bytes, size_t(w) * size_t(texel_bytes), w, h, float(w), float(h)};
  }
  ~GuardedLevel() { munmap(base_, size_); }
  GuardedLevel(const GuardedLevel&) = delete;
  GuardedLevel& operator=(const GuardedLevel&) = delete;
  const shading::TextureLevel& level() const { return level_; }
  std::byte* texels() { return const_cast<std::byte*>(level_.data); }

 private:
  std::byte* base_ = nullptr;
  size_t size_ = 0;
  shading::TextureLevel level_;
};

TEST(PcfSimd, KernelsNeverReadPastTheMap) {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  for (auto [w, h] : {std::pair{8, 4}, {9, 5}, {12, 6}, {37, 23}}) {
    for (TexelFormat f : {TexelFormat::d16, TexelFormat::d24, TexelFormat::d32f}) {
      GuardedLevel map(w, h, f == TexelFormat::d16 ? 2 : 4);
      for (size_t k = 0; k < size_t(w) * size_t(h); ++k) {
        const float z = depth(rng);
        if (f == TexelFormat::d16) reinterpret_cast<uint16_t*>(map.texels())[k] = uint16_t(z * 65535.0f);
        if (f == TexelFormat::d24) reinterpret_cast<uint32_t*>(map.texels())[k] = uint32_t(z * 16777215.0f) | 0xAB000000u;
        if (f == TexelFormat::d32f) reinterpret_cast<float*>(map.texels())[k] = z;
      }
      switch (f) {
        case TexelFormat::d16: check_format<TexelFormat::d16>(map.level(), rng, "d16 guarded"); break;
        case TexelFormat::d24: check_format<TexelFormat::d24>(map.level(), rng, "d24 guarded"); break;
        default: check_format<TexelFormat::d32f>(map.level(), rng, "d32f guarded"); break;
      }
    }
  }
}

// Rows 2^15 − 1, 2^15 and 40000 texels apart (a level as plain data, row_bytes beyond any map's or target's):
// the short path computes its pair offsets with 16-bit multiplies, which hold for a pitch below 2^15 only, so a
// level with a wider pitch must take the full path and still equal the scalar kernel.
TEST(PcfSimd, KernelsHandleRowPitchesAroundSixteenBits) {
  std::mt19937 rng(2718);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  const int w = 12, h = 6;
  for (size_t pitch : {size_t(32767), size_t(32768), size_t(40000)}) {
    for (TexelFormat f : {TexelFormat::d16, TexelFormat::d24, TexelFormat::d32f}) {
      const size_t bpt = f == TexelFormat::d16 ? 2 : 4;
      std::vector<std::byte> storage(size_t(h - 1) * pitch * bpt + size_t(w) * bpt);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          std::byte* p = storage.data() + (size_t(y) * pitch + size_t(x)) * bpt;
          const float z = depth(rng);
          if (f == TexelFormat::d16) *reinterpret_cast<uint16_t*>(p) = uint16_t(z * 65535.0f);
          if (f == TexelFormat::d24) *reinterpret_cast<uint32_t*>(p) = uint32_t(z * 16777215.0f) | 0xAB000000u;
          if (f == TexelFormat::d32f) *reinterpret_cast<float*>(p) = z;
        }
      const shading::TextureLevel L{storage.data(), pitch * bpt, w, h, float(w), float(h)};
      switch (f) {
        case TexelFormat::d16: check_format<TexelFormat::d16>(L, rng, "d16 wide pitch"); break;
        case TexelFormat::d24: check_format<TexelFormat::d24>(L, rng, "d24 wide pitch"); break;
        default: check_format<TexelFormat::d32f>(L, rng, "d32f wide pitch"); break;
      }
    }
  }
}

}  // namespace
