// The interface every shadow technique implements, and the registry that finds the implementation of a
// vocabulary.h technique. A technique plans one light's maps (which targets, passes, matrices and viewports,
// from the light, its settings and the scene's bounds), builds them (its map passes), reads them in the camera
// pass (scalar and eight-wide visibility, bit-identical to each other) and describes them for export (one
// MapRecord per file, with every pass's matrices). The frame renderer (scenes/frame) only talks to this
// interface; adding a technique is its own files plus one row in registry.cpp (docs/architecture.md).
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/renderer.h"
#include "shading/techniques/caster_geometry.h"
#include "shading/techniques/light_frustum.h"
#include "shading/techniques/shadow_filters.h"
#include "shading/techniques/vocabulary.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// A bad setting found while planning; what() names the setting (e.g. `lights[1].shadow.params.split_plane`).
struct TechniqueError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The light as every technique sees it.
struct LightDesc {
  LightType type = LightType::directional;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels (spot, hemispherical: the axis), unit length
  float range = 50.0f;                     // spot, point, hemispherical: metres
  float outer_angle = 0.4f;                // spot: cone half-angle, radians
};

// A light's shadow settings once the scene's values and the frame's overrides are merged.
struct ShadowConfig {
  Technique technique = Technique::shadowmap;
  FilterKind filter = FilterKind::pcf;
  FilterParams filter_params;
  BiasParams bias;
  bool cull_front = false;
  int map_size = 1024;
  DepthFormat depth_format = DepthFormat::d16;
  std::map<std::string, ParamValue> params;  // the technique's own parameters (checked with param_problem)
  std::string where = "shadow.params.";      // prefix naming a parameter in messages
  // Keys the frame's overrides gave (the command line's options): named "params.<key>" in messages, which the
  // CLI turns into the option, rather than `where` + key.
  std::set<std::string> overridden;
};

// Reads a technique's parameters from a ShadowConfig: the given value, or the ParamSpec's default.
class Params {
 public:
  explicit Params(const ShadowConfig& c) : c_(c) {}
  bool flag(std::string_view key) const;
  double number(std::string_view key) const;
  std::string text(std::string_view key) const;  // choice and text parameters
  bool given(std::string_view key) const { return c_.params.count(std::string(key)) != 0; }
  std::string where(std::string_view key) const {
    return (c_.overridden.count(std::string(key)) ? std::string("params.") : c_.where) + std::string(key);
  }

 private:
  const ParamSpec& spec(std::string_view key) const;
  const ShadowConfig& c_;
};

// The camera a frame is seen through, for the techniques that follow the view (cascades, LiSPSM, frustum faces).
struct CameraView {
  glm::mat4 view{1.0f}, proj{1.0f};  // GL conventions: the camera looks down −z of its view space
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit; view distance = dot(p − eye, forward)
  float near = 0.1f, far = 100.0f;       // view distances of the projection's clip planes
  bool perspective = true;
};

// What the camera actually sees (sample-distribution fitting), from a depth-only pre-pass over the receivers:
// per screen tile of covered pixels, its rectangle in normalised device x, y and the range of view distances
// of its pixels; and their overall range. The pyramid of a tile's rectangle between its two distances holds
// every visible point of the tile (visible_body in view_frustum.h turns it into points). Empty when nothing is
// covered.
struct VisibleTile {
  glm::vec2 ndc_min{0.0f}, ndc_max{0.0f};
  float near = 0.0f, far = 0.0f;  // view distances
};
struct VisibleSamples {
  std::vector<VisibleTile> tiles;
  float min_distance = 0.0f, max_distance = 0.0f;
};

// The camera's visible surface, pixel by pixel: what the camera pass will shade at each pixel, from a pre-pass
// that draws exactly what it draws (scenes/frame/camera_surface.h), for techniques that work on the camera's
// own samples (the irregular z-buffer). GL order: pixel (x, y) at index y · width + x, row 0 at the bottom.
struct CameraSurface {
  int width = 0, height = 0;
  std::vector<uint8_t> covered;     // 1 where a surface is visible; elsewhere the other values are 0
  std::vector<glm::vec3> position;  // world space, perspective-correct at the pixel centre
  std::vector<glm::vec3> normal;    // unit normal of the triangle's plane, on the side the camera sees
  // How far a shadow ray's origin leaves the surface along `normal`: the ray-cast reference's ε, 10⁻⁴ × the
  // diagonal of the scene's bounds (docs/ground-truth.md).
  float epsilon = 0.0f;
  size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
};

// What a plan may look at besides the light: the scene's bounds and the camera.
struct PlanInputs {
  Box casters;                     // bounds of every shadow caster
  Box receivers;                   // the camera frustum's part of the receivers' bounds (camera_receiver_box)
  Box scene_receivers;             // bounds of every receiver, wherever the camera looks
  glm::mat4 camera_view_proj{1.0f};
  glm::vec3 eye{0.0f};
  CameraView camera;
  // The camera's visible samples, computed on first call (a camera depth pre-pass) and kept for the frame;
  // null where the caller has none to offer.
  std::function<const VisibleSamples&()> visible;
  // Every scene instance's world box and flags (the tutorial's automatic frustum works object by object).
  std::vector<ObjectBounds> objects;
  // The light's fitted box of the previous frame of a sequence, read and updated by fits that smooth over
  // time (fit = tutorial); null for a single frame.
  FitMemory* fit_memory = nullptr;
  // The camera's visible surface per pixel (a camera pre-pass), computed on first call and kept for the frame;
  // null where the caller has none to offer.
  std::function<const CameraSurface&()> surface;
};

// One pass of an exported map: its viewport in the image and its matrices.
struct MapPassRecord {
  std::string label;
  raster::Rect viewport;
  glm::mat4 world_to_camera{1.0f}, world_to_ndc{1.0f};
};

// One exported map (an EXR file): the target it reads, or `values` (row-major, lower-left origin) where what
// the lookups compare with is not the target's depth; the matrices of the whole map and of each pass.
struct MapRecord {
  const raster::DepthTarget* target = nullptr;
  std::vector<float> values;
  std::string technique, encoding;
  glm::mat4 world_to_camera{1.0f}, world_to_ndc{1.0f};
  std::vector<MapPassRecord> passes;  // empty for a single full-image pass
};

// A figure a technique reports about its last build (`--stats`, `--json`): a name and a value, e.g. the
// milliseconds of one step or a count.
struct TechniqueStat {
  std::string name;
  double value = 0.0;
};

// One light's shadow for one frame: planned by the registry's factory, then built, read and exported.
class LightShadow {
 public:
  virtual ~LightShadow() = default;
  virtual raster::DrawStats build(raster::Renderer& renderer, const CasterGeometry& casters) = 0;
  // Visibility in [0, 1] of a batch of points (a quad's): the technique's run-time choices made once per batch.
  virtual void visibility(std::span<const ShadowQuery> q, std::span<float> vis) const = 0;
  // The same for up to eight points (a quad pair's), bit-identical per point.
  virtual void visibility_x8(std::span<const ShadowQuery> q, std::span<float> vis) const { visibility(q, vis); }
  virtual std::vector<MapRecord> maps() const = 0;
  // For the aliasing measure (scenes/frame/aliasing.h): the continuous texel coordinates, in the map that
  // point p reads, of p (out[0]) and of each of `others` in that same map (out[1..]), so a quad's derivatives
  // never mix two maps. False where p reads no map or the technique does not measure its aliasing.
  virtual bool texel_coords(glm::vec3 p, std::span<const glm::vec3> others, std::span<glm::vec2> out) const {
    (void)p, (void)others, (void)out;
    return false;
  }
  // The technique's own figures about its last build (its steps' costs, its counts); empty for most.
  virtual std::vector<TechniqueStat> stats() const { return {}; }
};

// How the camera pass applies a technique: through LightShadow::visibility in the lighting sum, or as extra
// receiver passes over the shaded frame (the projective technique of 2000, scenes/frame/frame_projective.h).
enum class Application : uint8_t { none, light_visibility, receiver_passes };

struct TechniqueImpl {
  Technique id;
  Application application;
  // light_visibility only: plans a light's maps. Throws TechniqueError naming a bad setting.
  std::unique_ptr<LightShadow> (*plan)(const LightDesc& light, const ShadowConfig& config, const PlanInputs& in);
};

// Every built technique, one row each (registry.cpp); techniques the vocabulary marks unbuilt have none.
std::span<const TechniqueImpl> registry();
const TechniqueImpl* find_impl(Technique t);

SHADOWLAB_ISA_END
}  // namespace shading::tech
