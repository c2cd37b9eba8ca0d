// The camera pass's per-pixel record of the visible surface (what a renderer calls AOVs): world position,
// geometric normal, window depth, and per light the shadow factor its technique returned. CameraShader fills it
// when FrameConfig::surface_record is set; the ray-cast reference (scenes/reference/) and the error report read
// it. Pixels are in GL order: index y · width + x, row 0 at the bottom of the frame (CONVENTIONS.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "scenes/io/exr_image.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

struct SurfaceRecord {
  int width = 0, height = 0;
  size_t lights = 0;
  // Per pixel. Where `covered` is 0 nothing was drawn and the other values are 0.
  std::vector<uint8_t> covered;
  std::vector<glm::vec3> position;  // world space, perspective-correct interpolation at the pixel centre
  // Unit normal of the triangle's plane (from the position's screen derivatives over the 2x2 quad), on the side
  // the camera sees.
  std::vector<glm::vec3> normal;
  std::vector<float> depth;         // window depth in [0, 1] as the depth test saw it (before d24 rounding); 1 uncovered
  // Per pixel and light (index pixel · lights + light).
  // lit_facing: the light reaches the point (n·l > 0 with the shading normal, inside the spot cone and range)
  // and its instance receives shadows, so the light's technique was asked for a shadow factor.
  std::vector<uint8_t> lit_facing;
  // The technique's shadow factor in [0, 1] where lit_facing, else 1 (also 1 for technique none). For lights
  // applied as receiver passes (projective) it is the product of the factors of the caster maps that the
  // passes multiplied into the pixel (before the frame buffer's 8-bit rounding).
  std::vector<float> visibility;

  SurfaceRecord() = default;
  SurfaceRecord(int w, int h, size_t light_count);
  size_t pixels() const { return size_t(width) * size_t(height); }
  size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
  // Multiplies the factor `f` into light `light`'s visibility at the pixel whose centre is `frag` (integer +
  // 0.5), where that light is lit-facing: how shadows applied in later passes (projective receiver passes) are
  // recorded. Each pixel belongs to one tile, so passes drawn in parallel never touch the same value.
  void multiply_visibility(float frag_x, float frag_y, size_t light, float f) {
    const size_t p = index(int(frag_x), int(frag_y)) * lights + light;
    if (lit_facing[p]) visibility[p] *= f;
  }
};

// What `shadowlab render --aov` can ask for, by name: position, normal, visibility, depth.
enum class AovChannel : uint8_t { position, normal, visibility, depth };
inline constexpr const char* kAovNames[] = {"position", "normal", "visibility", "depth"};
std::optional<AovChannel> parse_aov_channel(std::string_view name);

// The record as EXR channels, in the order asked: position -> P.X P.Y P.Z, normal -> N.X N.Y N.Z, depth -> Z,
// visibility -> per light `lightK.V` (the technique's factor, 1 where not lit-facing) and `lightK.facing` (1 where
// lit-facing), and always `A` (1 where covered). Uncovered pixels hold 0 (V: 1).
scenes::io::ExrImage aov_image(const SurfaceRecord& record, const std::vector<AovChannel>& channels);

SHADOWLAB_ISA_END
}  // namespace frame
