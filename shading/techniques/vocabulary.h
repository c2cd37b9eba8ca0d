// The one vocabulary of shadow settings, shared by the technique layer, the scene model, the frame library and
// the command line: light types, techniques, filters, bias modes and depth formats with their names and
// one-line descriptions, the table of per-technique defaults (which light types each serves, map size and depth
// format) and each technique's own parameters. Header-only and constexpr, with no dependency beyond
// raster/formats.h, so every layer can read it; the implementations of the techniques are found through
// technique.h (the interface and the registry of implementations, registry.cpp).
#pragma once
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "raster/formats.h"

namespace shading::tech {

using raster::DepthFormat;

enum class LightType : uint8_t { directional, spot, point, hemispherical };

// How a light's shadow is computed. `none`: the light casts no shadows.
enum class Technique : uint8_t {
  none,
  shadowmap,      // classic single map: orthographic (directional) or perspective (spot)
  cube,           // six 90° faces around a point light
  paraboloid,     // dual paraboloid (one paraboloid for a hemispherical light)
  pyramid,        // 180° light: one square map split into four triangles
  projective,     // per-caster black-on-white projective textures (2000)
  cascades,       // cascaded maps over slices of the view frustum (directional)
  lispsm,         // light-space perspective shadow map (directional)
  frustum_faces,  // perspective maps cut from the light-facing faces of the view frustum (directional, 2003)
  esm,            // exponential shadow map: exp(c z), blurred (filtered.h)
  vsm,            // variance shadow map: (z, z^2), blurred, Chebyshev bound
  evsm2,          // exponential variance shadow map, positive warp only
  evsm4,          // exponential variance shadow map, positive and negative warps
  pcss,           // percentage-closer soft shadows: blocker search, penumbra from the light's size (pcss.h)
  irregular,      // irregular z-buffer: casters tested exactly at the camera's samples (irregular.h)
};

// How a map is read. Each is a compile-time filter type (shadow_filters.h); the choice is made once per batch.
enum class FilterKind : uint8_t { hard, pcf, poisson, stratified, rotated, early_bail };

// Which depth bias is applied.
enum class BiasMode : uint8_t { none, constant, slope, offset, normal };

// All bias values; `mode` picks the one used. Depth values are the map's [0, 1] scale.
struct BiasParams {
  BiasMode mode = BiasMode::slope;
  float constant = 0.005f;      // constant: ref -= constant
  float slope = 0.005f;         // slope: ref -= clamp(slope · tan(acos(N·L)), 0, slope_max)
  float slope_max = 0.01f;
  float offset_factor = 1.1f;   // offset: glPolygonOffset(factor, units) in the depth pass, no shader bias
  float offset_units = 4.0f;
  float normal_offset = 0.02f;  // normal: receiver moved this far (metres) along its normal, no depth bias
  bool operator==(const BiasParams&) const = default;
};

// Reading parameters shared by the Poisson family.
struct FilterParams {
  int taps = 4;                      // 4 or 16
  float spread = 1.0f / 700.0f;      // disc radius in shadow-map texture coordinates
  bool pcf_taps = false;             // each Poisson tap is a hardware 2×2 PCF lookup instead of one compare
  bool stratify_world = false;       // stratified: hash world position rounded to 1 mm instead of the pixel
  bool tutorial = false;             // the tutorial's arithmetic: 1 - 0.2 per shadowed tap, its GLSL random
  bool operator==(const FilterParams&) const = default;
};

// A name with a one-line description, for `shadowlab list`, the docs and error messages.
struct NamedEntry {
  std::string_view name;
  std::string_view description;
};

// ---- Technique parameters: the per-technique extras a scene gives in `shadow.params` and the command line
// sets with the option named here. Each technique lists its own; every technique that reads a map also takes
// the filter parameters (kFilterParams).
enum class ParamKind : uint8_t { flag, number, integer, choice, text };

// A parameter's value as a scene file or an option gives it.
using ParamValue = std::variant<bool, double, std::string>;

struct ParamSpec {
  std::string_view key;       // the key in a scene's shadow.params
  std::string_view option;    // the command-line option (flags also get --no-...)
  ParamKind kind = ParamKind::flag;
  std::string_view fallback;  // the default, as text
  std::string_view help;
  double lo = 0.0, hi = 0.0;  // number, integer: the accepted range
  std::array<std::string_view, 5> choices{};  // choice: the accepted values
  std::string_view range_note{};  // number: why the range ends where it does, added to a range refusal
};

inline constexpr ParamSpec kFilterParams[] = {
    {"pcf_taps", "--pcf-taps", ParamKind::flag, "false", "Poisson filters: each tap is a hardware 2x2 PCF lookup"},
    {"stratify", "--stratify", ParamKind::choice, "pixel",
     "stratified filter seed: the pixel, or the world position rounded to 1 mm", 0, 0, {"pixel", "world"}},
    {"poisson_variant", "--poisson-variant", ParamKind::choice, "shadowlab",
     "poisson, stratified, rotated: the taps averaged with an integer hash (shadowlab), or the tutorial's "
     "1 - 0.2 per shadowed tap with its GLSL random (tutorial)",
     0, 0, {"shadowlab", "tutorial"}},
};
inline constexpr ParamSpec kClassicParams[] = {
    {"fit", "--fit", ParamKind::choice, "auto",
     "directional light box: the view frustum's part of the scene box (auto), the tutorial's fixed box (fixed), "
     "or the tutorial's potential receivers and casters, object by object (tutorial)",
     0, 0, {"auto", "fixed", "tutorial"}},
    {"fit_cutoff", "--fit-cutoff", ParamKind::number, "0",
     "fit = tutorial: receivers whose nearest point is farther than this from the camera (metres, along its view) "
     "are dropped; 0: the camera's far plane", 0, 1e6},
    {"fit_smoothing", "--fit-smoothing", ParamKind::number, "0.75",
     "fit = tutorial, across the frames of one run (--frames, --animate): the box grows at once and shrinks by "
     "1 - fit_smoothing of the difference per frame (0: no smoothing)", 0, 0.99},
};
inline constexpr ParamSpec kParaboloidParams[] = {
    {"paraboloid_pack", "--paraboloid-pack", ParamKind::choice, "float",
     "paraboloid depth storage: float, or base-256 packed into an RGBA8 target", 0, 0, {"float", "rgba8"}},
    {"split_plane", "--split-plane", ParamKind::text, "light",
     "paraboloid split plane normal: light (its direction), x, y, z, -x, -y, -z or a,b,c"},
};
inline constexpr ParamSpec kProjectiveParams[] = {
    {"projective_mode", "--projective-mode", ParamKind::choice, "multipass",
     "projective: a multiply pass per caster, or up to max_textures maps in one pass", 0, 0,
     {"multipass", "single-pass"}},
    {"max_textures", "--projective-textures", ParamKind::integer, "4",
     "projective single-pass: shadow textures per draw (more casters: extra passes)", 1, 8},
    {"caster_shade", "--caster-shade", ParamKind::number, "0", "projective: the shade a caster's mask is drawn with",
     0, 1},
    {"lod_bias", "--lod-bias", ParamKind::number, "0", "projective: mip level bias of the mask lookups", 0, 8},
    {"blur_passes", "--blur-passes", ParamKind::integer, "0",
     "projective: blur each mask by drawing it onto itself at an offset this many times (bilinear lookups at "
     "+-blur_offset texels; 0: none)", 0, 16},
    {"blur_offset", "--blur-offset", ParamKind::number, "0.5",
     "projective, blur_passes > 0: the offset of the lookups in texels (0.5: a 1/4, 1/2, 1/4 tent per pass)", 0.05,
     1, {}, "beyond one texel a pass would read past its neighbours"},
    {"fade_start", "--fade-start", ParamKind::number, "0", "projective: distance where the shadow starts to fade",
     0, 1e6},
    {"fade_end", "--fade-end", ParamKind::number, "0", "projective: distance where the shadow has faded (0: never)",
     0, 1e6},
    {"fade_lookup", "--fade-lookup", ParamKind::choice, "formula",
     "projective: the fade's strength from a linear ramp (formula), or a LINEAR lookup of a 1-D texture of "
     "fade_table indexed by distance over fade_start..fade_end (texture, the article's)", 0, 0,
     {"formula", "texture"}},
    {"fade_table", "--fade-table", ParamKind::text, "linear",
     "projective, fade_lookup = texture: the strengths from fade_start to fade_end: linear (1,0: the formula's "
     "ramp), smoothstep, or 2 to 256 comma-separated values in [0, 1]"},
    {"decimate", "--decimate", ParamKind::flag, "true",
     "projective: draw each mask from the caster clustered to half a map texel (same silhouette, fewer triangles)"},
    {"caster_reach", "--caster-reach", ParamKind::number, "0",
     "projective: maps only for casters near the view frustum: whose shadow volume, cut this far (metres) beyond "
     "the caster, reaches it (0: every caster)", 0, 1e6},
};

// Shared by the view-following techniques (cascades, lispsm, frustum-faces).
inline constexpr ParamSpec kViewRangeParam = {
    "view_range", "--view-range", ParamKind::choice, "scene",
    "cascades, lispsm, frustum-faces: cover the view frustum where receivers can be, or only what the camera "
    "sees (a camera depth pre-pass: sample distribution)", 0, 0, {"scene", "visible"}};
inline constexpr ParamSpec kMapLayoutParam = {
    "map_layout", "--map-layout", ParamKind::choice, "atlas",
    "cascades, frustum-faces: all maps in one atlas target (two per row) or one target each", 0, 0,
    {"atlas", "separate"}};
inline constexpr ParamSpec kLispsmParams[] = {kViewRangeParam};
inline constexpr ParamSpec kFaceParams[] = {
    {"face_warp", "--face-warp", ParamKind::choice, "exact",
     "frustum-faces: each map exactly covers its face (projection centre at the eye), or its centre is moved "
     "back by LiSPSM's rule", 0, 0, {"exact", "lispsm"}},
    kMapLayoutParam,
    kViewRangeParam,
};

// The filterable maps (esm, vsm, evsm2, evsm4) and PCSS (docs/filtered-shadows.md). The exponent limits are
// where 32-bit float storage overflows: ESM stores exp(c·z) with z in [0, 1], so c <= ln(FLT_MAX) = 88.72;
// EVSM stores exp(c·x) and its square with x in [-1, 1], so c <= ln(FLT_MAX) / 2 = 44.36.
inline constexpr ParamSpec kBlurParam = {
    "blur_radius", "--blur-radius", ParamKind::integer, "2",
    "esm, vsm, evsm2, evsm4, cascades' and cube's moments: box blur radius in texels of the separable blur passes (0: no blur)", 0, 16};
inline constexpr ParamSpec kMomentMipsParam = {
    "moment_mips", "--moment-mips", ParamKind::choice, "linear",
    "esm, vsm, evsm2, evsm4, cascades' and cube's moments: mip chain of the blurred map, read at the level of "
    "detail of the receiver's screen derivatives: trilinear (linear), nearest level (nearest) or level 0 only (none)",
    0, 0, {"linear", "nearest", "none"}};
inline constexpr ParamSpec kLightBleedParam = {
    "light_bleed", "--light-bleed", ParamKind::number, "0.2",
    "vsm, evsm2, evsm4 (also as cascades' and cube's moments): light-bleeding reduction, the Chebyshev bound p remapped by linstep(amount, 1, p)", 0,
    0.99};
inline constexpr ParamSpec kMinVarianceParam = {
    "min_variance", "--min-variance", ParamKind::number, "0.00002",
    "vsm (also as cascades' and cube's moments): smallest variance in the Chebyshev bound (in depth units squared)", 0, 0.01};
inline constexpr ParamSpec kEsmCParam = {
    "esm_c", "--esm-c", ParamKind::number, "80", "esm (also as cascades' and cube's moments): the exponent c of exp(c z); larger is sharper, less leaking",
    1, 88.72, {}, "exp(c z) overflows 32-bit float storage for c above ln(FLT_MAX) = 88.72"};
inline constexpr ParamSpec kEvsmPositiveParam = {
    "evsm_positive", "--evsm-positive", ParamKind::number, "40", "evsm2, evsm4 (also as cascades' and cube's moments): exponent of the positive warp",
    0.1, 44.36, {}, "the second moment exp(2 c) overflows 32-bit float storage for c above 44.36"};
inline constexpr ParamSpec kEvsmNegativeParam = {
    "evsm_negative", "--evsm-negative", ParamKind::number, "5", "evsm4 (also as cascades' and cube's moments): exponent of the negative warp", 0.1, 44.36,
    {}, "the second moment exp(2 c) overflows 32-bit float storage for c above 44.36"};
inline constexpr ParamSpec kEvsmMinVarianceParam = {
    "evsm_min_variance", "--evsm-min-variance", ParamKind::number, "0.0000001",
    "evsm2, evsm4 (also as cascades' and cube's moments): smallest variance in depth units squared, scaled by each warp's slope squared", 0, 0.01};
inline constexpr ParamSpec kEsmParams[] = {kEsmCParam, kBlurParam, kMomentMipsParam};
inline constexpr ParamSpec kVsmParams[] = {kBlurParam, kMomentMipsParam, kLightBleedParam, kMinVarianceParam};
inline constexpr ParamSpec kEvsmParams[] = {
    kEvsmPositiveParam, kEvsmNegativeParam, kEvsmMinVarianceParam, kBlurParam, kMomentMipsParam, kLightBleedParam,
};
// evsm2 has no negative warp: --evsm-negative with it is an unknown option, not one that silently does nothing.
inline constexpr ParamSpec kEvsm2Params[] = {
    kEvsmPositiveParam, kEvsmMinVarianceParam, kBlurParam, kMomentMipsParam, kLightBleedParam,
};
inline constexpr ParamSpec kMomentsParam = {
    "moments", "--moments", ParamKind::choice, "none",
    "cascades, cube: each slice's or face's map compared with the filter (none), or turned into blurred "
    "filterable moments as the esm, vsm, evsm2 and evsm4 techniques, with their parameters", 0, 0,
    {"none", "esm", "vsm", "evsm2", "evsm4"}};
inline constexpr ParamSpec kLightAngleParam = {
    "light_angle", "--light-angle", ParamKind::number, "1",
    "pcss, and cascades with soft_shadows = pcss: the directional light's angular diameter in degrees (the sun: 0.53)",
    0, 30};
inline constexpr ParamSpec kLightRadiusParam = {
    "light_radius", "--light-radius", ParamKind::number, "0.1",
    "pcss (spot light), and cube with soft_shadows = pcss: the light's radius in metres", 0, 100};
inline constexpr ParamSpec kSoftShadowsParam = {
    "soft_shadows", "--soft-shadows", ParamKind::choice, "none",
    "cascades, cube: each slice's or face's map read through the light's filter (none), or with PCSS (pcss): "
    "blocker search and penumbra from the light's size (cascades: light_angle, in each slice's own texels; cube: "
    "light_radius, across the faces)", 0, 0, {"none", "pcss"}};
// The cube's moments are blurred face by face (docs/filtered-shadows.md).
inline constexpr ParamSpec kCubeParams[] = {
    {"seamless", "--seamless", ParamKind::flag, "true",
     "cube: filter across face edges (GL_TEXTURE_CUBE_MAP_SEAMLESS; with moments, the bilinear lookup)"},
    kMomentsParam,
    kEsmCParam,
    kBlurParam,
    kMomentMipsParam,
    kLightBleedParam,
    kMinVarianceParam,
    kEvsmPositiveParam,
    kEvsmNegativeParam,
    kEvsmMinVarianceParam,
    kSoftShadowsParam,
    kLightRadiusParam,
};
inline constexpr ParamSpec kCascadeParams[] = {
    {"cascades", "--cascades", ParamKind::integer, "4", "cascades: number of slices of the view frustum", 1, 4},
    {"split_lambda", "--split-lambda", ParamKind::number, "0.75",
     "cascades: practical split scheme, 1 logarithmic, 0 uniform", 0, 1},
    {"stabilize", "--stabilize", ParamKind::flag, "false",
     "cascades: texel-snapped maps around each slice's bounding sphere (no shimmer, less resolution)"},
    {"cascade_blend", "--cascade-blend", ParamKind::number, "0",
     "cascades: fraction of a slice, at its far end, blended into the next slice's map", 0, 0.5},
    {"cascade_warp", "--cascade-warp", ParamKind::choice, "none",
     "cascades: each slice's map orthographic, or warped by LiSPSM", 0, 0, {"none", "lispsm"}},
    kMomentsParam,
    kSoftShadowsParam,
    kLightAngleParam,
    kMapLayoutParam,
    kViewRangeParam,
    kEsmCParam,
    kBlurParam,
    kMomentMipsParam,
    kLightBleedParam,
    kMinVarianceParam,
    kEvsmPositiveParam,
    kEvsmNegativeParam,
    kEvsmMinVarianceParam,
};
inline constexpr ParamSpec kPcssParams[] = {kLightAngleParam, kLightRadiusParam};

// The irregular z-buffer (docs/irregular.md): samples per pixel and the grid's cell bound.
inline constexpr ParamSpec kIrregularParams[] = {
    {"samples_per_pixel", "--samples-per-pixel", ParamKind::integer, "1",
     "irregular: shadow samples per pixel, 1 (the pixel centre), 8 or 32 (on the pixel's footprint, antialiased)",
     1, 32},
    {"cell_bound", "--cell-bound", ParamKind::integer, "64",
     "irregular: most samples per light-space grid cell; a fuller cell refines the grid (up to map_size cells a side)",
     1, 1e6},
};

// ---- The defaults table: one row per technique, indexed by Technique.
inline constexpr uint8_t light_bit(LightType t) { return uint8_t(1u << unsigned(t)); }
inline constexpr uint8_t kAllLights = 0xF;

struct TechniqueInfo {
  Technique id;
  std::string_view name;
  std::string_view description;
  uint8_t lights;              // light_bit() of every light type it serves
  bool built;                  // implemented (a row in registry.cpp); a scene or option naming an unbuilt one is refused
  uint32_t map_size;           // texels per side: of the map, per face or per caster
  DepthFormat depth_format;
  std::string_view encoding;   // what the map stores (EXR `shadowlab:encoding`)
  std::span<const ParamSpec> params;  // besides kFilterParams, which every technique reading a map takes
  bool reads_filter;           // takes the filter, bias and kFilterParams
};

inline constexpr TechniqueInfo kTechniques[] = {
    {Technique::none, "none", "the light casts no shadows", kAllLights, true, 0, DepthFormat::d16,
     "", {}, false},
    {Technique::shadowmap, "shadowmap",
     "classic shadow map: orthographic for directional, perspective for spot lights",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d16,
     "window-depth", kClassicParams, true},
    {Technique::cube, "cube", "cube shadow map: six 90° faces around a point light",
     light_bit(LightType::point) | light_bit(LightType::hemispherical), true, 1024, DepthFormat::d16, "radial-distance", kCubeParams, true},
    {Technique::paraboloid, "paraboloid", "dual-paraboloid shadow map (one paraboloid for a hemispherical light)",
     light_bit(LightType::point) | light_bit(LightType::hemispherical), true, 1024, DepthFormat::d16, "radial-distance", kParaboloidParams, true},
    {Technique::pyramid, "pyramid", "pyramid shadow map: a 180° light in one square map split into four triangles",
     light_bit(LightType::hemispherical), true, 1024, DepthFormat::d16, "radial-distance", {},
     true},
    {Technique::projective, "projective",
     "per-caster projective shadow textures (black on white) cast onto receivers",
     light_bit(LightType::directional) | light_bit(LightType::spot) | light_bit(LightType::point), true, 128,
     DepthFormat::d16, "caster-mask", kProjectiveParams, false},
    {Technique::cascades, "cascades", "cascaded shadow maps: 1-4 slices of the view frustum, one map each",
     light_bit(LightType::directional), true, 1024, DepthFormat::d16, "window-depth", kCascadeParams, true},
    {Technique::lispsm, "lispsm", "light-space perspective shadow map: one map warped along the view direction",
     light_bit(LightType::directional), true, 2048, DepthFormat::d24, "window-depth", kLispsmParams, true},
    {Technique::frustum_faces, "frustum-faces",
     "perspective maps cut from the light-facing faces of the view frustum (2003)",
     light_bit(LightType::directional), true, 1024, DepthFormat::d24, "window-depth", kFaceParams, true},
    {Technique::esm, "esm", "exponential shadow map: exp(c z) blurred, visibility clamp(exp(c (z_occ - z)))",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d32f, "window-depth",
     kEsmParams, false},
    {Technique::vsm, "vsm", "variance shadow map: (z, z^2) blurred, Chebyshev upper bound",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d32f, "window-depth",
     kVsmParams, false},
    {Technique::evsm2, "evsm2", "exponential variance shadow map: positive warp exp(c z), two moments",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d32f, "window-depth",
     kEvsm2Params, false},
    {Technique::evsm4, "evsm4", "exponential variance shadow map: positive and negative warps, four moments",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d32f, "window-depth",
     kEvsmParams, false},
    {Technique::pcss, "pcss", "percentage-closer soft shadows: blocker search, penumbra from the light's size",
     light_bit(LightType::directional) | light_bit(LightType::spot), true, 1024, DepthFormat::d24, "window-depth",
     kPcssParams, false},
    {Technique::irregular, "irregular",
     "irregular z-buffer: every caster tested exactly against the camera's visible samples (no bias, no map)",
     light_bit(LightType::directional) | light_bit(LightType::spot) | light_bit(LightType::point), true, 4096, DepthFormat::d32f, "", kIrregularParams,
     false},
};

inline constexpr NamedEntry kLightTypeNames[] = {
    {"directional", "parallel rays from a direction (the sun)"},
    {"spot", "a cone from a position: direction, inner and outer half-angles, range"},
    {"point", "all directions from a position, up to a range"},
    {"hemispherical", "a point light shining into the half-space it faces (180°)"},
};
inline constexpr NamedEntry kFilterNames[] = {
    {"hard", "one nearest-texel comparison"},
    {"pcf", "hardware PCF: four comparisons blended bilinearly"},
    {"poisson", "PCF at poisson_taps points of a Poisson disc"},
    {"stratified", "Poisson taps chosen per pixel from the 16-point disc"},
    {"rotated", "the Poisson disc rotated per pixel"},
    {"early-bail", "four distant taps first, all 16 only on shadow edges"},
};
inline constexpr NamedEntry kBiasNames[] = {
    {"none", "no bias"},
    {"constant", "constant depth bias (0.005)"},
    {"slope", "0.005 * tan(acos(N.L)) clamped to [0, 0.01]"},
    {"offset", "polygon offset (factor, units) while building the map"},
    {"normal", "normal offset: the receiver moves along its normal before the lookup"},
};
inline constexpr NamedEntry kDepthFormatNames[] = {
    {"d16", "16-bit unorm depth"},
    {"d24", "24-bit unorm depth"},
    {"d32f", "32-bit float depth"},
};

static_assert(std::size(kTechniques) == size_t(Technique::irregular) + 1);
static_assert(std::size(kFilterNames) == size_t(FilterKind::early_bail) + 1);
static_assert(std::size(kBiasNames) == size_t(BiasMode::normal) + 1);
static_assert(std::size(kLightTypeNames) == size_t(LightType::hemispherical) + 1);
static_assert(std::size(kDepthFormatNames) == size_t(DepthFormat::d32f) + 1);
consteval bool techniques_in_enum_order() {
  for (size_t i = 0; i < std::size(kTechniques); ++i)
    if (size_t(kTechniques[i].id) != i) return false;
  return true;
}
static_assert(techniques_in_enum_order(), "kTechniques rows must follow the Technique enum");

constexpr const TechniqueInfo& info(Technique t) { return kTechniques[size_t(t)]; }
constexpr bool supports(Technique t, LightType l) { return (info(t).lights & light_bit(l)) != 0; }

namespace detail {
template <class Enum, size_t N>
constexpr std::optional<Enum> parse_in(const NamedEntry (&table)[N], std::string_view s) {
  for (size_t i = 0; i < N; ++i)
    if (table[i].name == s) return Enum(i);
  return std::nullopt;
}
}  // namespace detail

constexpr std::string_view to_string(Technique t) { return info(t).name; }
constexpr std::string_view to_string(LightType t) { return kLightTypeNames[size_t(t)].name; }
constexpr std::string_view to_string(FilterKind f) { return kFilterNames[size_t(f)].name; }
constexpr std::string_view to_string(BiasMode b) { return kBiasNames[size_t(b)].name; }
using raster::to_string;

constexpr std::optional<Technique> parse_technique(std::string_view s) {
  for (const TechniqueInfo& t : kTechniques)
    if (t.name == s) return t.id;
  return std::nullopt;
}
constexpr std::optional<LightType> parse_light_type(std::string_view s) {
  return detail::parse_in<LightType>(kLightTypeNames, s);
}
constexpr std::optional<FilterKind> parse_filter(std::string_view s) {
  return detail::parse_in<FilterKind>(kFilterNames, s);
}
constexpr std::optional<BiasMode> parse_bias_mode(std::string_view s) {
  return detail::parse_in<BiasMode>(kBiasNames, s);
}
constexpr std::optional<DepthFormat> parse_depth_format(std::string_view s) {
  return detail::parse_in<DepthFormat>(kDepthFormatNames, s);
}

// The largest map side a technique accepts: where its maps share one target (cube: 3 × 2 faces; paraboloid:
// two side by side; cascades and frustum faces: an atlas two maps wide), that target stays within 16384 texels
// a side. The pyramid's side must also be even (map_size_problem).
constexpr int max_map_size(Technique t) {
  switch (t) {
    case Technique::cube: return 16384 / 3;
    case Technique::paraboloid:
    case Technique::cascades:
    case Technique::frustum_faces: return 16384 / 2;
    default: return 16384;
  }
}

// What is wrong with map side `size` for technique t; none when it is fine.
inline std::optional<std::string> map_size_problem(Technique t, int size) {
  const int lo = t == Technique::projective || t == Technique::none ? 1 : 16, hi = max_map_size(t);
  if (size < lo || size > hi)
    return std::to_string(size) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi) +
           (hi < 16384 ? " for technique " + std::string(info(t).name) + " (its maps share one target of at most 16384 "
                                                                          "texels a side)"
                       : std::string());
  if (t == Technique::pyramid && size % 2 != 0)
    return "the pyramid map side " + std::to_string(size) + " must be even (two halves per axis)";
  return std::nullopt;
}

// "directional, spot": the light types a technique serves, for `list` and error messages.
inline std::string light_names(uint8_t mask) {
  std::string out;
  for (size_t i = 0; i < std::size(kLightTypeNames); ++i)
    if (mask & (1u << i)) out += (out.empty() ? "" : ", ") + std::string(kLightTypeNames[i].name);
  return out;
}

// The parameter `key` of technique t (its own, or a filter parameter where it reads a map); null if none.
constexpr const ParamSpec* find_param(Technique t, std::string_view key) {
  for (const ParamSpec& p : info(t).params)
    if (p.key == key) return &p;
  if (info(t).reads_filter)
    for (const ParamSpec& p : kFilterParams)
      if (p.key == key) return &p;
  return nullptr;
}

// Why technique t cannot shadow a light of type l (empty when it can): not built yet, or not for that type.
inline std::string refusal(Technique t, LightType l) {
  if (!info(t).built)
    return "technique " + std::string(info(t).name) + " is not built yet";
  if (!supports(t, l))
    return "technique " + std::string(info(t).name) + " does not serve " + std::string(to_string(l)) +
           " lights (it serves: " + light_names(info(t).lights) + ")";
  return {};
}

// What is wrong with `value` for a parameter of this spec: the wrong kind, out of range or not among the
// choices; none when it is fine. Text values are checked by the technique itself.
inline std::optional<std::string> value_problem(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.kind) {
    case ParamKind::flag:
      if (!std::holds_alternative<bool>(value)) return std::string("expected true or false");
      return std::nullopt;
    case ParamKind::number:
    case ParamKind::integer: {
      const double* v = std::get_if<double>(&value);
      char range[64];
      std::snprintf(range, sizeof range, "[%g, %g]", spec.lo, spec.hi);
      const bool whole = spec.kind == ParamKind::integer;
      if (!v || !std::isfinite(*v) || *v < spec.lo || *v > spec.hi || (whole && *v != std::floor(*v)))
        return std::string(whole ? "expected a whole number in " : "expected a number in ") + range +
               (spec.range_note.empty() ? std::string() : " (" + std::string(spec.range_note) + ")");
      return std::nullopt;
    }
    case ParamKind::choice: {
      const std::string* v = std::get_if<std::string>(&value);
      std::string known;
      for (std::string_view c : spec.choices)
        if (!c.empty()) {
          if (v && *v == c) return std::nullopt;
          known += (known.empty() ? "" : ", ") + std::string(c);
        }
      return "expected one of: " + known;
    }
    case ParamKind::text:
      if (!std::holds_alternative<std::string>(value)) return std::string("expected a string");
      return std::nullopt;
  }
  return std::nullopt;
}

// What is wrong with `value` as parameter `key` of technique t: a key it does not take, or value_problem.
inline std::optional<std::string> param_problem(Technique technique, const std::string& key, const ParamValue& value) {
  if (const ParamSpec* spec = find_param(technique, key)) return value_problem(*spec, value);
  std::string known;
  auto add = [&](std::span<const ParamSpec> list) {
    for (const auto& p : list) known += (known.empty() ? "" : ", ") + std::string(p.key);
  };
  add(info(technique).params);
  if (info(technique).reads_filter) add(kFilterParams);
  return "technique " + std::string(to_string(technique)) + " takes no parameter '" + key + "' (it takes: " +
         (known.empty() ? std::string("none") : known) + ")";
}

}  // namespace shading::tech
