// Render target storage, clears and per-texel access (the slow, exact path used by tests, files and readback).
#include "raster/target.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#include "raster/limits.h"
#include "raster/parallel_clear.h"
#include "raster/thread_pool.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

AlignedBuffer::AlignedBuffer(size_t bytes) : size_(bytes) {
  // Buffers of 2 MiB and more are aligned to 2 MiB and offered to the kernel as transparent huge pages: zeroing
  // a 2048² RGBA32F target (64 MiB) took 16,384 page faults, measured at about 0.7 s in a virtual machine, and
  // takes 32 with huge pages. The contents and the alignment the code relies on (64 bytes) are unchanged.
  constexpr size_t kHuge = size_t(2) << 20;
  const size_t align = bytes >= kHuge ? kHuge : 64;
  const size_t rounded = bytes == 0 ? 64 : (bytes + align - 1) / align * align;
  void* p = std::aligned_alloc(align, rounded);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (align == kHuge) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: its failure changes nothing
#endif
  std::memset(p, 0, rounded);
  data_.reset(static_cast<std::byte*>(p));
}

void AlignedBuffer::Free::operator()(std::byte* p) const { std::free(p); }

void check_target_size(int width, int height) {
  auto check = [](const char* what, int v) {
    if (v < 1 || v > kMaxTargetSize)
      throw TargetSizeError(std::string(what) + " " + std::to_string(v) + " is outside 1.." +
                            std::to_string(kMaxTargetSize));
  };
  check("width", width);
  check("height", height);
}

namespace {
int round_up(int v, int m) { return (v + m - 1) / m * m; }

// Elements per row: the width rounded up to the tile size, then one 64-byte cache line more. A tile-multiple row
// is an even number of lines (a power of two of them at widths such as 1024 or 2048), so the rows of a tile fall
// into the same few sets of a 64-set L1 cache and evict one another while tile execution walks down them. With
// an odd number of lines per row, 64 consecutive rows start in 64 different sets. Measured on the 2-core AMD EPYC
// of the Zen 4 generation (2026-11-30, AVX-512 path, 2 threads, without llvmpipe, seven rounds alternating, a
// noisy hour): the depth-only back end of the dragon's 871k triangles into a 2048² d32f map 10.31–10.88 → 9.03–10.25
// ms (medians 10.67 → 9.31), of 10^6 small triangles 9.79 → 9.33 ms (medians), of 2·10^4 large ones unchanged; the
// one-lookup PCF pass sampling such a map 2.20–2.25 → 2.09–2.13 ms, 16 Poisson taps unchanged (19.1–19.4 ms); the
// blur of the filterable maps (bench/blur_bench.cpp) 24.0–24.2 → 21.8–22.2 ms per core. (A 2026-11-28 test of
// this padding, with older kernels on a noisier day, saw the Poisson pass slower; not reproduced here.)
int row_pitch(int width, size_t bytes_per_texel) {
  constexpr size_t kLine = 64;  // texels are 2, 4, 8 or 16 bytes: each divides a line
  static_assert(kTileSize * 2 % kLine == 0, "a tile-multiple row of the narrowest texels is whole lines");
  return round_up(width, kTileSize) + int(kLine / bytes_per_texel);
}

uint32_t depth_to_raw(float z, DepthFormat f) {
  z = std::clamp(z, 0.0f, 1.0f);
  switch (f) {
    case DepthFormat::d16: return uint32_t(std::nearbyint(double(z) * 65535.0));
    case DepthFormat::d24: return uint32_t(std::nearbyint(double(z) * 16777215.0));
    case DepthFormat::d32f: return std::bit_cast<uint32_t>(z);
  }
  return 0;
}
}  // namespace

DepthTarget::DepthTarget(int width, int height, DepthFormat format)
    : width_(width), height_(height), format_(format) {
  check_target_size(width, height);
  pitch_ = row_pitch(width, bytes_per_texel());
  padded_height_ = round_up(height, kTileSize);
  storage_ = AlignedBuffer(size_t(pitch_) * size_t(padded_height_) * bytes_per_texel());
  clear(1.0f);
}

DepthTarget::DepthTarget(const DepthTarget& o)
    : width_(o.width_), height_(o.height_), pitch_(o.pitch_), padded_height_(o.padded_height_), format_(o.format_),
      storage_(o.storage_.size()) {
  o.resolve_clear();
  std::memcpy(storage_.data(), o.storage_.data(), o.storage_.size());
}

DepthTarget::DepthTarget(DepthTarget&& o) noexcept
    : width_(o.width_), height_(o.height_), pitch_(o.pitch_), padded_height_(o.padded_height_), format_(o.format_),
      storage_(std::move(o.storage_)), clear_pending_(o.clear_pending_.load()), clear_raw_(o.clear_raw_) {}

DepthTarget& DepthTarget::operator=(const DepthTarget& o) {
  if (this != &o) *this = DepthTarget(o);
  return *this;
}

DepthTarget& DepthTarget::operator=(DepthTarget&& o) noexcept {
  width_ = o.width_, height_ = o.height_, pitch_ = o.pitch_, padded_height_ = o.padded_height_;
  format_ = o.format_;
  storage_ = std::move(o.storage_);
  clear_pending_.store(o.clear_pending_.load());
  clear_raw_ = o.clear_raw_;
  return *this;
}

void DepthTarget::clear(float depth) {
  std::lock_guard lock(clear_mutex_);
  clear_raw_ = depth_to_raw(depth, format_);
  clear_pending_.store(true, std::memory_order_release);
}

std::optional<uint32_t> DepthTarget::take_pending_clear() {
  std::lock_guard lock(clear_mutex_);
  if (!clear_pending_.load(std::memory_order_relaxed)) return std::nullopt;
  clear_pending_.store(false, std::memory_order_release);
  return clear_raw_;
}

void DepthTarget::resolve_clear_slow() const {
  std::lock_guard lock(clear_mutex_);
  if (!clear_pending_.load(std::memory_order_relaxed)) return;  // another thread resolved it meanwhile
  const_cast<DepthTarget*>(this)->fill(clear_raw_, 0, 0, pitch_, padded_height_);
  clear_pending_.store(false, std::memory_order_release);
}

void DepthTarget::fill(uint32_t raw, int x0, int y0, int w, int h) {
  std::byte* base = storage_.data();
  for (int y = y0; y < y0 + h; ++y) {
    const size_t at = size_t(y) * size_t(pitch_) + size_t(x0);
    if (format_ == DepthFormat::d16) std::fill_n(reinterpret_cast<uint16_t*>(base) + at, w, uint16_t(raw));
    else std::fill_n(reinterpret_cast<uint32_t*>(base) + at, w, raw);
  }
}

void DepthTarget::fill_tile(uint32_t raw, int tx, int ty) {
  const int x0 = tx << kTileSizeLog2;
  const bool last = x0 + kTileSize >= width_;  // the rightmost tile column
  fill(raw, x0, ty << kTileSizeLog2, last ? pitch_ - x0 : kTileSize, kTileSize);
}

uint32_t DepthTarget::raw(int x, int y) const {
  return format_ == DepthFormat::d16 ? row<uint16_t>(y)[x] : row<uint32_t>(y)[x];
}

float DepthTarget::value(int x, int y) const {
  const uint32_t r = raw(x, y);
  switch (format_) {
    case DepthFormat::d16: return float(double(r) / 65535.0);
    case DepthFormat::d24: return float(double(r) / 16777215.0);
    case DepthFormat::d32f: return std::bit_cast<float>(r);
  }
  return 0.0f;
}

float srgb_encode(float l) {
  l = std::clamp(l, 0.0f, 1.0f);
  return l <= 0.0031308f ? 12.92f * l : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float e) {
  e = std::clamp(e, 0.0f, 1.0f);
  return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

ColorTarget::ColorTarget(int width, int height, ColorFormat format, bool srgb)
    : width_(width),
      height_(height),
      format_(format),
      srgb_(srgb && format == ColorFormat::rgba8),
      channels_(float_channels(format)) {
  check_target_size(width, height);
  pitch_ = row_pitch(width, bytes_per_texel(format));
  padded_height_ = round_up(height, kTileSize);
  storage_ = AlignedBuffer(size_t(pitch_) * size_t(padded_height_) * bytes_per_texel(format));
}

void ColorTarget::clear(const glm::vec4& c) {
  // The workers' clear (parallel_clear.h) run inline on the calling thread: one way to store the value.
  ThreadPool inline_pool(0);
  clear_on_workers(*this, c, inline_pool);
}

glm::vec4 ColorTarget::read(int x, int y) const {
  if (channels_ > 0) {
    const float* p = row32f(y) + size_t(x) * size_t(channels_);
    glm::vec4 c(0.0f, 0.0f, 0.0f, 1.0f);
    for (int i = 0; i < channels_; ++i) c[i] = p[i];
    return c;
  }
  const uint8_t* p = row8(y) + size_t(x) * 4;
  glm::vec4 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f);
  if (srgb_) c = {srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b), c.a};
  return c;
}

SHADOWLAB_ISA_END
}  // namespace raster
