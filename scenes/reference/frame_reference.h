// A frame and its exact shadow in two calls: reference_for renders the camera view once with shadows off and a
// surface record, builds the BVH over the scene's casters (exactly the triangles the shadow passes rasterise:
// scenes::flatten_by_coverage with InstanceFilter::casters, masked casters alpha-tested; receiver-only instances cast nothing there and here) and casts the
// rays; score_config renders one configuration of the same view and scores it against that reference.
#pragma once
#include "raster/renderer.h"
#include "scenes/frame/frame.h"
#include "scenes/reference/exact_visibility.h"
#include "scenes/reference/shadow_score.h"
#include "scenes/scene.h"
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

struct FrameReference {
  frame::Frame shadows_off;  // the view with technique none, its surface record kept
  ExactVisibility exact;
  size_t triangles = 0;      // in the BVH
  double bvh_ms = 0.0;       // building it
};

// `config`'s size and camera are used; its shadow settings are replaced by technique none. `epsilon` < 0: the
// default_epsilon of the scene. Throws frame::FrameError for a bad size or camera, ReferenceError from Embree.
// `textures`: the scene's material textures (loaded here when null); masked casters are tested against their
// alpha as in the depth passes; only this call reads them.
FrameReference reference_for(const scenes::Scene& scene, frame::FrameConfig config, raster::Renderer& renderer,
                             float epsilon = -1.0f, const scenes::io::SceneTextures* textures = nullptr);

struct ScoredFrame {
  frame::Frame frame;  // with its surface record
  FrameScore score;
  double score_ms = 0.0;  // scoring alone (the frame's own times are in frame.stats)
};

// Renders `config` (its surface record switched on) and scores it. Throws frame::FrameError for a bad setting,
// ReferenceError when the frame's covered pixels differ from the reference's (another size or camera).
ScoredFrame score_config(const scenes::Scene& scene, frame::FrameConfig config, raster::Renderer& renderer,
                         const FrameReference& ref, const ScoreOptions& options = {},
                         const scenes::io::SceneTextures* textures = nullptr);

SHADOWLAB_ISA_END
}  // namespace reference
