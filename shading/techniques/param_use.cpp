// When a declared parameter does nothing (see param_use.h).
#include "shading/techniques/param_use.h"

#include <initializer_list>

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

bool one_of(std::string_view key, std::initializer_list<std::string_view> keys) {
  for (std::string_view k : keys)
    if (k == key) return true;
  return false;
}

// The moment keys a `moments` kind reads, as moment_params (filtered.cpp) and the techniques' blur read them.
std::optional<std::string> unread_moment_key(const Params& p, std::string_view key) {
  if (!one_of(key, {"blur_radius", "moment_mips", "esm_c", "light_bleed", "min_variance", "evsm_positive",
                    "evsm_negative", "evsm_min_variance"}))
    return std::nullopt;
  const std::string kind = p.text("moments");
  if (kind == "none") return "is read with a moments kind only (moments is none: no moment map is built)";
  bool read = one_of(key, {"blur_radius", "moment_mips"});
  if (kind == "esm") read |= key == "esm_c";
  if (kind == "vsm") read |= one_of(key, {"light_bleed", "min_variance"});
  if (kind == "evsm2" || kind == "evsm4") read |= one_of(key, {"light_bleed", "evsm_positive", "evsm_min_variance"});
  if (kind == "evsm4") read |= key == "evsm_negative";
  if (read) return std::nullopt;
  return "is not read with moments = " + kind;
}

}  // namespace

std::optional<std::string> unread_param(const ShadowConfig& c, LightType light, std::string_view key) {
  const Params p(c);
  switch (c.technique) {
    case Technique::pcss:
      if (key == "light_angle" && light != LightType::directional)
        return std::string("is a directional light's size; a spot light's is light_radius (metres)");
      if (key == "light_radius" && light == LightType::directional)
        return std::string("is a spot light's size; a directional light's is light_angle (degrees)");
      return std::nullopt;
    case Technique::cascades:
    case Technique::cube:
      if (one_of(key, {"light_angle", "light_radius"}) && p.text("soft_shadows") != "pcss")
        return std::string("the light's size is read by soft_shadows = pcss only");
      return unread_moment_key(p, key);
    case Technique::shadowmap:
      if (one_of(key, {"fit", "fit_cutoff", "fit_smoothing"}) && light != LightType::directional)
        return std::string("sizes a directional light's box; a spot light's map follows its cone");
      if (one_of(key, {"fit_cutoff", "fit_smoothing"}) && p.text("fit") != "tutorial")
        return "applies to fit = tutorial only (fit is " + p.text("fit") + ")";
      return std::nullopt;
    case Technique::paraboloid:
      if (key == "split_plane" && light == LightType::hemispherical)
        return std::string("divides a point light's two paraboloids; a hemispherical light's one faces its direction");
      return std::nullopt;
    default: return std::nullopt;
  }
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
