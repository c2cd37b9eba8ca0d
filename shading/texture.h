// Texture2D: what a shader samples. Either owns its texels or is a view over a render target's memory (no
// copy: a depth pass's target is sampled as it was rendered), with an optional box-filtered mip chain. Row 0
// is t = 0, the bottom row of what was rendered (CONVENTIONS). Lookups (lookup.h) read only TextureLevel.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <span>

#include <glm/vec4.hpp>

#include "raster/state.h"
#include "raster/target.h"
#include "shading/mip_chain.h"
#include "shading/texel_format.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// One mip level as lookups see it: plain data, no behaviour beyond addressing.
struct TextureLevel {
  const std::byte* data = nullptr;  // texel (0, 0): s = 0, t = 0, the bottom-left texel
  size_t row_bytes = 0;             // bytes from one row to the next (a target's pitch, or width × texel size)
  int width = 0, height = 0;
  float fwidth = 0.0f, fheight = 0.0f;  // the same sizes as floats, for coordinate scaling

  const std::byte* row(int j) const { return data + size_t(j) * row_bytes; }
};

// A 2D texture handle. Copies are cheap and share texels (owned storage is reference-counted). A view does not
// keep its target alive: the target must outlive every lookup through the view, and the view sees whatever
// the target holds at lookup time.
class Texture2D {
 public:
  Texture2D() = default;
  // Owned, zero-filled storage; with `mipmaps`, the full chain down to 1 × 1 (fill level 0, then call
  // generate_mips). Throws std::invalid_argument for a side outside 1..kMaxTextureSize.
  Texture2D(int width, int height, TexelFormat format, bool mipmaps = false);

  // Views over render target memory, optionally of a sub-rectangle (lower-left origin, inside the target): the
  // region is then sampled as a texture of its own, its edges the ones wrap modes see. Throws
  // std::invalid_argument for a region outside the target.
  static Texture2D view(const raster::DepthTarget& target);
  static Texture2D view(const raster::DepthTarget& target, const raster::Rect& region);
  static Texture2D view(const raster::ColorTarget& target);
  static Texture2D view(const raster::ColorTarget& target, const raster::Rect& region);

  // An owned texture filled from linear values, `channels` floats per texel (1 to 4; missing components
  // read as 0, alpha as 1), rows bottom first (row 0 is t = 0), encoded with encode_texel.
  static Texture2D from_floats(int width, int height, TexelFormat format, int channels, std::span<const float> values,
                               bool mipmaps = false);

  bool empty() const { return levels_ == 0; }
  TexelFormat format() const { return format_; }
  int levels() const { return levels_; }
  int width(int level = 0) const { return level_[size_t(level)].width; }
  int height(int level = 0) const { return level_[size_t(level)].height; }
  const TextureLevel& level(int l) const { return level_[size_t(l)]; }
  const std::array<TextureLevel, kMaxMipLevels>& all_levels() const { return level_; }
  // True when level `l` lives in this texture's own storage (writable); false for the level 0 of a view.
  bool owns_level(int l) const { return l >= owned_from_ && l < levels_; }

  // Decoded texel (slow, exact path for tests and files): what a NEAREST lookup of its centre returns.
  glm::vec4 texel(int i, int j, int level = 0) const;
  // Encodes and stores one texel of an owned level; throws std::logic_error on a view's level.
  void set_texel(int i, int j, const glm::vec4& value, int level = 0);
  // Raw row of an owned level (for loaders that write encoded texels directly); throws like set_texel.
  std::byte* mutable_row(int level, int j);

  // Builds levels 1.. by box filtering (mip_chain.h), each from the one above. A texture created without mips
  // (or a view) first gets storage for the full chain; a view keeps level 0 on the target, so call this again
  // after the target changes.
  void generate_mips();

 private:
  void allocate_levels(int first, int count);

  TexelFormat format_ = TexelFormat::d32f;
  int levels_ = 0;
  int owned_from_ = 0;  // levels [owned_from_, levels_) are in storage_
  std::array<TextureLevel, kMaxMipLevels> level_{};
  std::shared_ptr<raster::AlignedBuffer> storage_;
};

SHADOWLAB_ISA_END
}  // namespace shading
