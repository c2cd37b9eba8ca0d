// The registry: one row per built technique, naming how the camera pass applies it and its factory, plus the
// parameter reader every factory uses. The vocabulary's defaults table (vocabulary.h) holds each technique's
// names, light types, defaults and parameters; a test checks that the two agree on which are built.
#include <cstdlib>

#include "shading/techniques/cascades.h"
#include "shading/techniques/classic.h"
#include "shading/techniques/filtered.h"
#include "shading/techniques/frustum_faces.h"
#include "shading/techniques/irregular.h"
#include "shading/techniques/omni_read.h"
#include "shading/techniques/pcss.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr TechniqueImpl kRegistry[] = {
    {Technique::none, Application::none, nullptr},
    {Technique::shadowmap, Application::light_visibility, &plan_classic},
    {Technique::cube, Application::light_visibility, &plan_cube},
    {Technique::paraboloid, Application::light_visibility, &plan_paraboloid},
    {Technique::pyramid, Application::light_visibility, &plan_pyramid},
    {Technique::projective, Application::receiver_passes, nullptr},
    {Technique::cascades, Application::light_visibility, &plan_cascades},
    {Technique::lispsm, Application::light_visibility, &plan_lispsm},
    {Technique::frustum_faces, Application::light_visibility, &plan_frustum_faces},
    {Technique::esm, Application::light_visibility, &plan_esm},
    {Technique::vsm, Application::light_visibility, &plan_vsm},
    {Technique::evsm2, Application::light_visibility, &plan_evsm2},
    {Technique::evsm4, Application::light_visibility, &plan_evsm4},
    {Technique::pcss, Application::light_visibility, &plan_pcss},
    {Technique::irregular, Application::light_visibility, &plan_irregular},
};

}  // namespace

std::span<const TechniqueImpl> registry() { return kRegistry; }

const TechniqueImpl* find_impl(Technique t) {
  for (const TechniqueImpl& i : kRegistry)
    if (i.id == t) return &i;
  return nullptr;
}

const ParamSpec& Params::spec(std::string_view key) const {
  const ParamSpec* s = find_param(c_.technique, key);
  if (!s) throw std::logic_error("technique " + std::string(to_string(c_.technique)) + " reads parameter " +
                                 std::string(key) + " that vocabulary.h does not declare for it");
  return *s;
}

namespace {
// The given value of `key`, checked against its spec; null when absent.
const ParamValue* checked(const ShadowConfig& c, const ParamSpec& spec) {
  const auto it = c.params.find(std::string(spec.key));
  if (it == c.params.end()) return nullptr;
  if (auto why = value_problem(spec, it->second)) throw TechniqueError(c.where + it->first + ": " + *why);
  return &it->second;
}
}  // namespace

bool Params::flag(std::string_view key) const {
  const ParamSpec& s = spec(key);
  if (const ParamValue* v = checked(c_, s)) return std::get<bool>(*v);
  return s.fallback == "true";
}

double Params::number(std::string_view key) const {
  const ParamSpec& s = spec(key);
  if (const ParamValue* v = checked(c_, s)) return std::get<double>(*v);
  return std::strtod(std::string(s.fallback).c_str(), nullptr);
}

std::string Params::text(std::string_view key) const {
  const ParamSpec& s = spec(key);
  if (const ParamValue* v = checked(c_, s)) return std::get<std::string>(*v);
  return std::string(s.fallback);
}

SHADOWLAB_ISA_END
}  // namespace shading::tech
