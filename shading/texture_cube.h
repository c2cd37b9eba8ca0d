// TextureCube: six square Texture2D faces in GL's order (+X, −X, +Y, −Y, +Z, −Z), each owned or a view of a
// render target (six targets, or six regions of one atlas), sampled by direction (lookup_cube.h).
#pragma once
#include <array>

#include "shading/cube_face.h"
#include "shading/texture.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

class TextureCube {
 public:
  TextureCube() = default;
  // Six owned, zero-filled faces of size × size texels.
  TextureCube(int size, TexelFormat format, bool mipmaps = false);
  // Any six faces: they must be square, of one size, one format and one level count (std::invalid_argument
  // otherwise). Face f's texel row 0 is t = 0 of GL's table (cube_face_view renders it that way).
  explicit TextureCube(std::array<Texture2D, 6> faces);

  bool empty() const { return faces_[0].empty(); }
  const Texture2D& face(int f) const { return faces_[size_t(f)]; }
  Texture2D& face(int f) { return faces_[size_t(f)]; }
  const Texture2D& face(CubeFace f) const { return faces_[size_t(f)]; }
  Texture2D& face(CubeFace f) { return faces_[size_t(f)]; }
  TexelFormat format() const { return faces_[0].format(); }
  int size(int level = 0) const { return faces_[0].width(level); }
  int levels() const { return faces_[0].levels(); }

  // Box-filtered mips of every face (each face on its own; GL does not filter across faces either).
  void generate_mips();

 private:
  std::array<Texture2D, 6> faces_;
};

SHADOWLAB_ISA_END
}  // namespace shading
