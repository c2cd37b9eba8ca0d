// The camera shader's wide path (CameraShader::fragment_pair, each light's visibility asked for a quad pair with
// the filters eight lanes wide) gives the same bits as its quad path (fragment(), forced with
// FrameConfig::quad_fragments): whole frames of the classic scenes with every filter and map format.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "scenes/frame/camera_shader.h"
#include "raster/quad_path_only.h"
#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "tests/support.h"

namespace {

static_assert(raster::HasPairFragmentStage<frame::CameraShader>, "the camera pass takes the wide path");
static_assert(!raster::HasPairFragmentStage<raster::QuadPathOnly<frame::CameraShader>>);

struct Read {
  const char* name;
  const char* filter;
  int taps;
  bool pcf_taps;
  const char* stratify = "pixel";
  const char* variant = "shadowlab";
};

const Read kReads[] = {
    {"hard", "hard", 4, false},
    {"pcf", "pcf", 4, false},
    {"poisson4", "poisson", 4, false},
    {"poisson16", "poisson", 16, false},
    {"poisson4_pcf", "poisson", 4, true},
    {"poisson16_pcf", "poisson", 16, true},
    {"stratified", "stratified", 4, false},
    {"stratified16_pcf_world", "stratified", 16, true, "world"},
    {"rotated", "rotated", 16, false},
    {"rotated4_pcf", "rotated", 4, true},
    {"early_bail", "early-bail", 16, false},
    {"early_bail_pcf", "early-bail", 16, true},
    {"poisson16_tutorial", "poisson", 16, false, "pixel", "tutorial"},
    {"stratified_tutorial", "stratified", 4, false, "pixel", "tutorial"},
    {"stratified16_pcf_world_tutorial", "stratified", 16, true, "world", "tutorial"},
    {"rotated_tutorial", "rotated", 16, true, "pixel", "tutorial"},
};

// Pixels (RGBA8 bytes) where two frames differ.
size_t bytes_differing(const raster::ColorTarget& a, const raster::ColorTarget& b) {
  size_t n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width() * 4; ++x) n += a.row8(y)[x] != b.row8(y)[x];
  return n;
}

void expect_paths_agree(const char* scene_name, raster::DepthFormat format, int map_size,
                        std::optional<shading::tech::Technique> technique = std::nullopt,
                        const std::map<std::string, shading::tech::ParamValue>& params = {},
                        const char* bias = "slope") {
  scenes::Scene scene = scenes::builtin_scene(scene_name);
  for (auto& l : scene.lights) l.shadow.depth_format = format;
  raster::Renderer renderer(testsupport::test_threads());
  for (const Read& r : kReads) {
    frame::FrameConfig o;
    o.width = 256, o.height = 144;  // odd quad pairs at the right edge are covered by triangle edges anyway
    o.filter = *shading::tech::parse_filter(r.filter);
    o.bias = *shading::tech::parse_bias_mode(bias);
    o.technique = technique;
    o.params = params;
    o.cull_front = true;
    o.poisson_taps = r.taps;
    o.params["pcf_taps"] = bool(r.pcf_taps);
    o.params["stratify"] = std::string(r.stratify);
    o.params["poisson_variant"] = std::string(r.variant);
    o.map_size = map_size;
    const frame::Frame wide = frame::render_frame(scene, o, renderer);
    o.quad_fragments = true;
    const frame::Frame quads = frame::render_frame(scene, o, renderer);
    EXPECT_EQ(bytes_differing(wide.color, quads.color), 0u)
        << scene_name << " " << r.name << " d" << int(format) << " map " << map_size;
  }
}

}  // namespace

TEST(CameraPair, TutorialWidePathEqualsQuadPath) {
  expect_paths_agree("tutorial", raster::DepthFormat::d16, 1024);
  expect_paths_agree("tutorial", raster::DepthFormat::d24, 512);
  expect_paths_agree("tutorial", raster::DepthFormat::d32f, 256);
}

TEST(CameraPair, SpotWidePathEqualsQuadPath) {
  expect_paths_agree("tutorial-spot", raster::DepthFormat::d16, 512);
  expect_paths_agree("tutorial-spot", raster::DepthFormat::d32f, 1024);
}

// The view-following techniques read one map per point, chosen per point: a quad pair that spans two slices
// or two faces, and the blend band between cascades, read the same bits on both paths.
TEST(CameraPair, ViewFollowingWidePathEqualsQuadPath) {
  using shading::tech::Technique;
  expect_paths_agree("duel", raster::DepthFormat::d16, 512, Technique::cascades, {{"cascade_blend", 0.3}});
  expect_paths_agree("duel", raster::DepthFormat::d24, 1024, Technique::lispsm, {}, "constant");
  expect_paths_agree("tutorial", raster::DepthFormat::d24, 512, Technique::frustum_faces, {}, "normal");
  expect_paths_agree("tutorial", raster::DepthFormat::d16, 512, Technique::cascades,
                     {{"cascades", 3.0}, {"cascade_warp", std::string("lispsm")}}, "offset");
}
