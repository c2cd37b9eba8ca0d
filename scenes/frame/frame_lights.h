// From a scene light and the frame's overrides to what a frame is rendered with: the lighting model's Light,
// the light as the techniques see it (LightDesc) and its merged, checked shadow settings (ShadowConfig).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenes/frame/frame.h"
#include "scenes/scene_queries.h"
#include "shading/lighting.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

// A file-name part for `prefix` + "-" + `name`: characters other than letters, digits, '-' and '_' become '-',
// and an empty (or all-punctuation) name adds nothing, so a stem never ends in '-' ("light0", "light1-sun").
std::string name_stem(const std::string& prefix, const std::string& name);

struct ResolvedLight {
  shading::Light light;
  tech::LightDesc desc;
  tech::ShadowConfig config;
};

// A point, hemispherical or spot light's ambient illuminance (shading::Light::ambient, lux), the same at every
// point: its flux Φ reflected once by surfaces of albedo ½ and spread evenly over the surface of the scene's
// bounds, E = ½ · Φ / A with A = 2(ab + bc + ca) for a box of sides a, b, c. Φ = 4π·I for a point light, 2π·I
// for a hemispherical one, 2π(1 − cos outer)·I for a spot (its cone to the outer angle). A is at least 1 cm²; an
// empty box gives 0; a directional light 0 (its ambient is shading::Material::ambient of its own illuminance).
float ambient_illuminance(const scenes::Light& light, const scenes::Aabb& bounds);

// Throws FrameError naming the field: a technique the light's type does not take or that is not built, a map
// size, tap count or bias value out of range, a technique parameter of the wrong kind. `index` is the light's
// place in the scene, for messages naming lights[index].
ResolvedLight resolve_light(const scenes::Light& light, size_t index, const FrameConfig& config);

// Why the frame's technique parameter `key` would do nothing with these lights, as a FrameError's text
// (`params.esm_c: ...`): no light's technique takes it, or every light taking it leaves it unread with its
// settings (tech::unread_param). Nothing when some light reads it. Throws FrameError for a value its spec refuses.
std::optional<std::string> unread_override(const std::vector<ResolvedLight>& lights, const std::string& key,
                                           const tech::ParamValue& value);

// A light whose map is read as filterable moments (esm, vsm, evsm2, evsm4, or cascades' and cube's `moments`)
// bounds a receiver's visibility by the depths around it in the map, so a receiver missing from the map (an
// object that receives shadows but casts none) reads the cleared far depth there and its shadows fade or vanish
// (measured: ESM on a glTF chair whose ground was not in the map, 2.7 % of the pixels false-lit against 0.5 %).
// The warning's text for such a light (`index`: its place in the scene), naming those objects; nothing otherwise.
std::optional<std::string> moment_receiver_warning(const ResolvedLight& light, size_t index, const scenes::Scene& scene);

SHADOWLAB_ISA_END
}  // namespace frame
