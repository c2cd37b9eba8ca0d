// Texture2D storage, views over render targets, texel access and mip generation.
#include "shading/texture.h"

#include <stdexcept>
#include <string>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

namespace {

void check_size(int width, int height) {
  auto check = [](const char* what, int v) {
    if (v < 1 || v > kMaxTextureSize)
      throw std::invalid_argument(std::string("texture ") + what + " " + std::to_string(v) + " is outside 1.." +
                                  std::to_string(kMaxTextureSize));
  };
  check("width", width);
  check("height", height);
}

void check_region(const raster::Rect& r, int width, int height) {
  if (r.width < 1 || r.height < 1 || r.x < 0 || r.y < 0 || r.x > width - r.width || r.y > height - r.height)
    throw std::invalid_argument("texture view region (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ", " +
                                std::to_string(r.width) + " x " + std::to_string(r.height) + ") is not inside the " +
                                std::to_string(width) + " x " + std::to_string(height) + " target");
}

TextureLevel make_level(const std::byte* data, size_t row_bytes, int width, int height) {
  return TextureLevel{data, row_bytes, width, height, float(width), float(height)};
}

size_t align64(size_t v) { return (v + 63) / 64 * 64; }

}  // namespace

Texture2D::Texture2D(int width, int height, TexelFormat format, bool mipmaps) : format_(format) {
  check_size(width, height);
  level_[0] = make_level(nullptr, 0, width, height);
  levels_ = 1;
  allocate_levels(0, mipmaps ? mip_level_count(width, height) : 1);
}

void Texture2D::allocate_levels(int first, int count) {
  // Sizes of levels [first, first + count), tightly packed rows, each level 64-byte aligned.
  const int w0 = level_[0].width, h0 = level_[0].height;
  const size_t bpt = bytes_per_texel(format_);
  size_t total = 0;
  std::array<size_t, kMaxMipLevels> offset{};
  for (int l = first; l < first + count; ++l) {
    offset[size_t(l)] = total;
    total += align64(size_t(mip_size(w0, l)) * bpt * size_t(mip_size(h0, l)));
  }
  storage_ = std::make_shared<raster::AlignedBuffer>(total);
  for (int l = first; l < first + count; ++l) {
    const int w = mip_size(w0, l), h = mip_size(h0, l);
    level_[size_t(l)] = make_level(storage_->data() + offset[size_t(l)], size_t(w) * bpt, w, h);
  }
  owned_from_ = first;
  levels_ = first + count;
}

Texture2D Texture2D::view(const raster::DepthTarget& target) {
  return view(target, raster::Rect{0, 0, target.width(), target.height()});
}

Texture2D Texture2D::view(const raster::DepthTarget& target, const raster::Rect& region) {
  check_region(region, target.width(), target.height());
  Texture2D t;
  t.format_ = texel_format_of(target.format());
  const size_t bpt = target.bytes_per_texel();
  const std::byte* base = target.row<std::byte>(0);  // row<T> steps by pitch elements of T, so use bytes here
  const size_t row_bytes = size_t(target.pitch()) * bpt;
  t.level_[0] =
      make_level(base + size_t(region.y) * row_bytes + size_t(region.x) * bpt, row_bytes, region.width, region.height);
  t.levels_ = 1;
  t.owned_from_ = 1;
  return t;
}

Texture2D Texture2D::view(const raster::ColorTarget& target) {
  return view(target, raster::Rect{0, 0, target.width(), target.height()});
}

Texture2D Texture2D::view(const raster::ColorTarget& target, const raster::Rect& region) {
  check_region(region, target.width(), target.height());
  Texture2D t;
  t.format_ = texel_format_of(target.format(), target.srgb());
  const size_t bpt = bytes_per_texel(t.format_);
  const size_t row_bytes = size_t(target.pitch()) * bpt;
  const auto* base = reinterpret_cast<const std::byte*>(target.row8(0));
  t.level_[0] =
      make_level(base + size_t(region.y) * row_bytes + size_t(region.x) * bpt, row_bytes, region.width, region.height);
  t.levels_ = 1;
  t.owned_from_ = 1;
  return t;
}

Texture2D Texture2D::from_floats(int width, int height, TexelFormat format, int channels, std::span<const float> values,
                                 bool mipmaps) {
  if (channels < 1 || channels > 4) throw std::invalid_argument("from_floats: channels must be 1 to 4");
  check_size(width, height);
  if (values.size() != size_t(width) * size_t(height) * size_t(channels))
    throw std::invalid_argument("from_floats: " + std::to_string(values.size()) + " values for a " +
                                std::to_string(width) + " x " + std::to_string(height) + " x " +
                                std::to_string(channels) + " texture");
  Texture2D t(width, height, format, mipmaps);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
      const float* p = values.data() + (size_t(j) * size_t(width) + size_t(i)) * size_t(channels);
      for (int c = 0; c < channels; ++c) v[c] = p[c];
      t.set_texel(i, j, v);
    }
  if (mipmaps) t.generate_mips();
  return t;
}

glm::vec4 Texture2D::texel(int i, int j, int level) const {
  const TextureLevel& L = level_[size_t(level)];
  return decode_texel(format_, L.row(j), i);
}

std::byte* Texture2D::mutable_row(int level, int j) {
  if (!owns_level(level))
    throw std::logic_error("texture level " + std::to_string(level) + " is a view of a render target, not writable");
  const TextureLevel& L = level_[size_t(level)];
  return const_cast<std::byte*>(L.row(j));  // storage_ is ours and mutable
}

void Texture2D::set_texel(int i, int j, const glm::vec4& value, int level) {
  encode_texel(format_, mutable_row(level, j), i, value);
}

void Texture2D::generate_mips() {
  if (empty()) return;
  const int full = mip_level_count(level_[0].width, level_[0].height);
  if (levels_ < full) {
    // Keep owned level 0 (copying it into the new storage) or the view's level 0 as it is.
    if (owned_from_ == 0) {
      const TextureLevel old = level_[0];
      const auto old_storage = storage_;
      allocate_levels(0, full);
      for (int j = 0; j < old.height; ++j)
        std::copy_n(old.row(j), size_t(old.width) * bytes_per_texel(format_), mutable_row(0, j));
    } else {
      allocate_levels(1, full - 1);
    }
  }
  for (int l = 1; l < levels_; ++l) {
    const TextureLevel& s = level_[size_t(l - 1)];
    const TextureLevel& d = level_[size_t(l)];
    box_downsample(format_, s.data, s.row_bytes, s.width, s.height, mutable_row(l, 0), d.row_bytes, d.width, d.height);
  }
}

SHADOWLAB_ISA_END
}  // namespace shading
