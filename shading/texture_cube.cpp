// TextureCube construction and checks.
#include "shading/texture_cube.h"

#include <stdexcept>
#include <string>
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

TextureCube::TextureCube(int size, TexelFormat format, bool mipmaps) {
  for (auto& f : faces_) f = Texture2D(size, size, format, mipmaps);
}

TextureCube::TextureCube(std::array<Texture2D, 6> faces) : faces_(std::move(faces)) {
  const Texture2D& f0 = faces_[0];
  if (f0.empty()) throw std::invalid_argument("cube face 0 is empty");
  if (f0.width() != f0.height())
    throw std::invalid_argument("cube faces must be square; face 0 is " + std::to_string(f0.width()) + " x " +
                                std::to_string(f0.height()));
  for (int i = 1; i < 6; ++i) {
    const Texture2D& f = faces_[size_t(i)];
    if (f.empty() || f.width() != f0.width() || f.height() != f0.height() || f.format() != f0.format() ||
        f.levels() != f0.levels())
      throw std::invalid_argument("cube face " + std::to_string(i) +
                                  " differs from face 0 in size, format or mip levels");
  }
}

void TextureCube::generate_mips() {
  for (auto& f : faces_) f.generate_mips();
}

SHADOWLAB_ISA_END
}  // namespace shading
