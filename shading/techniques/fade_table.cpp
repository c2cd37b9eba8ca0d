// Fade tables of projective shadows: parsing, the texture, and its LINEAR lookup (see fade_table.h).
#include "shading/techniques/fade_table.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "shading/filter.h"
#include "shading/texel_format.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::optional<std::vector<float>> parse_fade_table(std::string_view text, std::string& why) {
  const std::string_view t = trim(text);
  if (t == "linear") return std::vector<float>{1.0f, 0.0f};
  if (t == "smoothstep") {
    std::vector<float> v(kSmoothstepTexels);
    for (int i = 0; i < kSmoothstepTexels; ++i) {
      const double x = double(i) / double(kSmoothstepTexels - 1);
      v[size_t(i)] = float(1.0 - x * x * (3.0 - 2.0 * x));
    }
    return v;
  }
  std::vector<float> v;
  size_t start = 0;
  while (start <= t.size()) {
    const size_t comma = t.find(',', start);
    const std::string_view item = trim(t.substr(start, comma == std::string_view::npos ? t.npos : comma - start));
    double x = 0.0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), x);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size()) {
      // Appended, not `"'" + std::string(item)`: GCC 12 warns (-Wrestrict, a false positive) about that form.
      why = std::string("'").append(item).append("' is not a number (expected linear, smoothstep, or 2 to ") +
            std::to_string(kMaxFadeTexels) + " comma-separated strengths in [0, 1])";
      return std::nullopt;
    }
    if (!(x >= 0.0 && x <= 1.0)) {
      why = "strength " + std::string(item) + " is outside [0, 1]";
      return std::nullopt;
    }
    v.push_back(float(x));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (v.size() < 2 || v.size() > size_t(kMaxFadeTexels)) {
    why = std::to_string(v.size()) + " strengths given; a table has 2 to " + std::to_string(kMaxFadeTexels);
    return std::nullopt;
  }
  return v;
}

Texture2D make_fade_texture(std::span<const float> strengths) {
  if (strengths.size() < 2 || strengths.size() > size_t(kMaxFadeTexels))
    throw std::invalid_argument("make_fade_texture: a fade table has 2 to 256 texels");
  std::vector<float> fade(strengths.size());
  for (size_t i = 0; i < fade.size(); ++i) fade[i] = 1.0f - strengths[i];
  return Texture2D::from_floats(int(fade.size()), 1, TexelFormat::r32f, 1, fade);
}

float fade_at(const Texture2D& table, float t) {
  const TextureLevel& L = table.level(0);
  const float u = (t > 0.0f ? (t < 1.0f ? t : 1.0f) : 0.0f) * float(L.width - 1);
  const float fl = std::floor(u);
  const int i0 = int(fl), i1 = i0 + 1 < L.width ? i0 + 1 : L.width - 1;
  const std::byte* row = L.row(0);
  using R = Texel<TexelFormat::r32f>;
  return lerp(u - fl, R::red(row, i0), R::red(row, i1));
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
