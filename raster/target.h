// Render targets: the depth and colour buffers a draw writes and a shader may later sample without copying.
// Memory is row-major with row 0 at the bottom (window y = 0, texture t = 0), rows padded to a multiple of the
// tile size so that tile execution can work on whole aligned 8-pixel rows, plus one cache line (target.cpp,
// row_pitch: the rows of a tile then fall into different L1 sets).
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include <glm/vec4.hpp>

#include "raster/formats.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// GL's sRGB transfer functions (exact formulas of the sRGB standard, in float).
float srgb_encode(float linear);
float srgb_decode(float encoded);

// Thrown for a size of 0 or beyond kMaxTargetSize. The message names the offending dimension.
struct TargetSizeError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Owns 64-byte aligned, zero-initialised storage of a given byte size.
class AlignedBuffer {
 public:
  AlignedBuffer() = default;
  explicit AlignedBuffer(size_t bytes);
  std::byte* data() { return data_.get(); }
  const std::byte* data() const { return data_.get(); }
  size_t size() const { return size_; }

 private:
  struct Free {
    void operator()(std::byte* p) const;
  };
  std::unique_ptr<std::byte[], Free> data_;
  size_t size_ = 0;
};

// A depth buffer in one of the formats of CONVENTIONS: d16 stores round(z·65535) as uint16, d24 stores
// round(z·16777215) in the low 24 bits of a uint32, d32f stores the float z clamped to [0, 1].
//
// clear() does not touch memory: it records the value, and the clear happens on first use. A draw into the
// target takes it over and clears each 64×64 tile on the worker that executes the tile, just before the tile's
// commands (Renderer::draw), so no thread makes a serial pass over the whole target. Any other access through
// the target (row(), raw(), value(), resolve_clear()) clears it whole first. A pointer taken earlier (a texture
// view over the target) sees the cleared values once a draw or such an access has resolved the clear.
class DepthTarget {
 public:
  DepthTarget(int width, int height, DepthFormat format);
  DepthTarget(const DepthTarget& o);
  DepthTarget(DepthTarget&& o) noexcept;
  DepthTarget& operator=(const DepthTarget& o);
  DepthTarget& operator=(DepthTarget&& o) noexcept;

  int width() const { return width_; }
  int height() const { return height_; }
  DepthFormat format() const { return format_; }
  // Elements (not bytes) between the starts of two consecutive rows.
  int pitch() const { return pitch_; }
  int padded_height() const { return padded_height_; }
  size_t bytes_per_texel() const { return format_ == DepthFormat::d16 ? 2 : 4; }

  // Clears every texel to the given depth (converted to the format; default 1.0 as in GL), on first use.
  void clear(float depth = 1.0f);
  // Carries out a pending clear now, on the calling thread.
  void resolve_clear() const {
    if (clear_pending_.load(std::memory_order_acquire)) resolve_clear_slow();
  }
  // For the renderer: takes over a pending clear (the stored value it clears to) so that the caller writes it
  // into every texel of the padded target before anything reads it; nullopt when none is pending.
  std::optional<uint32_t> take_pending_clear();
  // Writes the stored value `raw` into the texels [x0, x0 + w) × [y0, y0 + h) (a tile of the padded target).
  void fill(uint32_t raw, int x0, int y0, int w, int h);
  // fill() over tile (tx, ty) of the padded target (TileGrid's numbering); a tile of the rightmost column also
  // takes the rest of its rows (the pitch's extra cache line), so clearing every tile clears every texel.
  void fill_tile(uint32_t raw, int tx, int ty);

  // The stored value at pixel (x, y) (y = 0 is the bottom row) as a float in [0, 1]: code / max code for the
  // unorm formats, the float itself for d32f.
  float value(int x, int y) const;
  // The raw stored value: the unorm code, or the bit pattern of the float for d32f.
  uint32_t raw(int x, int y) const;

  template <class T>
  T* row(int y) {
    resolve_clear();
    return reinterpret_cast<T*>(storage_.data()) + size_t(y) * size_t(pitch_);
  }
  template <class T>
  const T* row(int y) const {
    resolve_clear();
    return reinterpret_cast<const T*>(storage_.data()) + size_t(y) * size_t(pitch_);
  }

 private:
  void resolve_clear_slow() const;

  int width_, height_, pitch_, padded_height_;
  DepthFormat format_;
  AlignedBuffer storage_;
  // The pending clear: its stored value, valid while clear_pending_ is set; the mutex orders concurrent
  // first uses (readers of a const target may race to resolve it).
  mutable std::atomic<bool> clear_pending_{false};
  uint32_t clear_raw_ = 0;
  mutable std::mutex clear_mutex_;
};

// A colour buffer: RGBA8 (unorm, optionally sRGB-encoded on write as GL_SRGB8_ALPHA8) or 32-bit float with
// four, two or one channels (RGBA32F, RG32F, R32F).
class ColorTarget {
 public:
  ColorTarget(int width, int height, ColorFormat format, bool srgb = false);

  int width() const { return width_; }
  int height() const { return height_; }
  ColorFormat format() const { return format_; }
  bool srgb() const { return srgb_; }
  int pitch() const { return pitch_; }
  int padded_height() const { return padded_height_; }
  // Floats per texel of a float target (4, 2 or 1), 0 for RGBA8.
  int channels() const { return channels_; }

  void clear(const glm::vec4& color);
  // Linear colour at (x, y): unorm values divided by 255 (and decoded from sRGB when the target is sRGB); a
  // float target's missing channels read 0 and its missing alpha 1.
  glm::vec4 read(int x, int y) const;
  // Stores a linear colour with GL's conversion: clamp to [0, 1], sRGB-encode if the target is sRGB, then
  // round(c · 255) for RGBA8; a float target stores its channels of the value unchanged. Inline: shaded draws
  // call it per pixel.
  void write(int x, int y, const glm::vec4& c) {
    if (channels_ > 0) {
      float* p = row32f(y) + size_t(x) * size_t(channels_);
      for (int i = 0; i < channels_; ++i) p[i] = c[i];
      return;
    }
    uint8_t* p = row8(y) + size_t(x) * 4;
    for (int i = 0; i < 4; ++i) {
      float v = std::clamp(c[i], 0.0f, 1.0f);
      if (srgb_ && i < 3) v = srgb_encode(v);
      p[i] = uint8_t(std::nearbyint(v * 255.0f));
    }
  }

  uint8_t* row8(int y) { return reinterpret_cast<uint8_t*>(storage_.data()) + size_t(y) * size_t(pitch_) * 4; }
  const uint8_t* row8(int y) const {
    return reinterpret_cast<const uint8_t*>(storage_.data()) + size_t(y) * size_t(pitch_) * 4;
  }
  // Row y of a float target: channels() floats per texel.
  float* row32f(int y) {
    return reinterpret_cast<float*>(storage_.data()) + size_t(y) * size_t(pitch_) * size_t(channels_);
  }
  const float* row32f(int y) const {
    return reinterpret_cast<const float*>(storage_.data()) + size_t(y) * size_t(pitch_) * size_t(channels_);
  }

 private:
  int width_, height_, pitch_, padded_height_;
  ColorFormat format_;
  bool srgb_;
  int channels_;
  AlignedBuffer storage_;
};

// Checks a requested target size, throwing TargetSizeError with a message like
// "width 0 is outside 1..16384" when it is out of range.
void check_target_size(int width, int height);

SHADOWLAB_ISA_END
}  // namespace raster
