// The frame side of the omnidirectional techniques (cube, paraboloid, pyramid): which lights use one and with
// what settings (the light's ShadowSettings, its `params` and the command-line overrides), building the map,
// its EXR with every pass's viewport and matrices, and the reader the camera pass snapshots.
#pragma once
#include <optional>
#include <span>

#include "cli/frame/frame.h"
#include "cli/frame/frame_lights.h"
#include "scenes/io/exr_map.h"
#include "shading/techniques/omni_read.h"

namespace frame {

struct OmniPlan {
  shading::tech::OmniKind kind = shading::tech::OmniKind::cube;
  shading::tech::OmniLight light;
  shading::tech::OmniSettings settings;
};

// The plan of a point or hemispherical light whose technique is cube, paraboloid or pyramid; none for any other
// light or technique. Throws std::invalid_argument naming the option (or the params key) for a bad value:
// --seamless / seamless, --paraboloid-pack / paraboloid_pack, --split-plane / split_plane, the `offset` bias
// (a distance written by the fragment shader gets no polygon offset), an odd pyramid map size, range <= 0.
// `index` is the light's place in the scene, for messages naming lights[index].shadow.params.KEY.
std::optional<OmniPlan> resolve_omni(const scenes::Light& light, const ResolvedLight& resolved,
                                     const FrameOptions& options, size_t index = 0);

// "x", "-y", ... or "a,b,c": the split plane's normal; none when the text is neither.
std::optional<glm::vec3> parse_split_plane(const std::string& text);

struct OmniMaps {
  OmniPlan plan;
  shading::tech::ShadowMapSet set;
};

OmniMaps plan_omni(const OmniPlan& plan);
raster::DrawStats build_omni(raster::Renderer& renderer, OmniMaps& maps, std::span<const glm::vec3> positions,
                             std::span<const uint32_t> indices);
// One EXR for the whole map (all faces, regions or hemispheres in one image), encoding radial-distance.
scenes::io::ExrMap omni_exr(const OmniMaps& maps);
shading::tech::OmniReader omni_reader(const OmniMaps& maps);

}  // namespace frame
