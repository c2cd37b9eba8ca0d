// Whole frames of the view-following techniques (cascades, LiSPSM, frustum faces) on the built-in `duel` and
// `tutorial` scenes: golden hashes, identical at 0, 1 and 2 threads; stabilised cascades whose maps do not
// change when the camera moves by a fraction of a texel (and tight ones that do, so the check can fail); the
// refusals a user meets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include <glm/geometric.hpp>

#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "tests/scenes/frame/golden.h"

namespace {

namespace tech = shading::tech;

struct Case {
  const char* name;
  const char* scene;
  tech::Technique technique;
  const char* params;  // key=value;key=value
  uint64_t expected;
};

void apply_params(frame::FrameConfig& o, const std::string& text) {
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = std::min(text.find(';', at), text.size());
    const std::string kv = text.substr(at, end - at);
    const size_t eq = kv.find('=');
    const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
    if (value == "true" || value == "false") o.params[key] = value == "true";
    else if (std::isdigit(static_cast<unsigned char>(value[0]))) o.params[key] = std::stod(value);
    else o.params[key] = value;
    at = end + 1;
  }
}

// Expected hashes at 320 × 180 with each technique's default map size and format.
const Case kCases[] = {
    {"duel_cascades", "duel", tech::Technique::cascades, "", 0x6568bf28bbf7019eull},
    {"duel_cascades2_separate", "duel", tech::Technique::cascades, "cascades=2;map_layout=separate", 0x1f585a443e74629dull},
    {"duel_cascades_stable_blend", "duel", tech::Technique::cascades, "stabilize=true;cascade_blend=0.2", 0x278c3a4129be6edaull},
    {"duel_cascades_visible", "duel", tech::Technique::cascades, "view_range=visible", 0x3b06233669c1ed40ull},
    {"duel_cascades_lispsm", "duel", tech::Technique::cascades, "cascade_warp=lispsm", 0x4e9999ca1e4fd146ull},
    {"duel_lispsm", "duel", tech::Technique::lispsm, "", 0xf3fd96f4c68b804full},
    {"duel_faces", "duel", tech::Technique::frustum_faces, "", 0xcbf3c16e1c0725eaull},
    {"tutorial_cascades", "tutorial", tech::Technique::cascades, "", 0xfa680df155240a5aull},
    {"tutorial_lispsm", "tutorial", tech::Technique::lispsm, "", 0x6f5b51570aaac9b2ull},
    {"tutorial_lispsm_visible", "tutorial", tech::Technique::lispsm, "view_range=visible", 0xffb32891ca7bded6ull},
    {"tutorial_faces", "tutorial", tech::Technique::frustum_faces, "", 0x11448459e8b77820ull},
    {"tutorial_faces_lispsm", "tutorial", tech::Technique::frustum_faces, "face_warp=lispsm;map_layout=separate", 0xa556d351c5bef05dull},
};

class ViewFollowingGolden : public testing::TestWithParam<Case> {};

TEST_P(ViewFollowingGolden, HashIsStableAcrossThreadCounts) {
  const Case& c = GetParam();
  const scenes::Scene scene = scenes::builtin_scene(c.scene);
  frame::FrameConfig o;
  o.width = 320;
  o.height = 180;
  o.technique = c.technique;
  apply_params(o, c.params);
  testsupport::expect_golden_frame(c.name, c.expected, scene, o, [&](const frame::Frame& f) {
    const auto maps = frame::export_maps(f);
    ASSERT_FALSE(maps.empty());
    for (const auto& m : maps) EXPECT_EQ(m.map.technique, tech::to_string(c.technique));
  });
}

INSTANTIATE_TEST_SUITE_P(Techniques, ViewFollowingGolden, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// The depth texels of every map of a frame, concatenated.
std::vector<float> map_texels(const frame::Frame& f) {
  std::vector<float> out;
  for (const auto& m : frame::export_maps(f)) out.insert(out.end(), m.map.z.begin(), m.map.z.end());
  return out;
}

std::vector<float> duel_maps_with_camera_shift(glm::vec3 shift, bool stabilize) {
  scenes::Scene scene = scenes::builtin_scene("duel");
  scene.cameras.at(0).position += shift;
  scene.cameras.at(0).target += shift;
  frame::FrameConfig o;
  o.width = 320;
  o.height = 180;
  o.technique = tech::Technique::cascades;
  o.params["stabilize"] = stabilize;
  raster::Renderer r(2);
  return map_texels(frame::render_frame(scene, o, r));
}

TEST(StabilisedCascades, MapsStayBitIdenticalWhenTheCameraMovesByAFractionOfATexel) {
  // The nearest cascade's texels are about a centimetre wide on `duel`; a millimetre is well under one.
  const glm::vec3 shift(0.0011f, 0.0007f, -0.0013f);
  const std::vector<float> a = duel_maps_with_camera_shift(glm::vec3(0.0f), true);
  const std::vector<float> b = duel_maps_with_camera_shift(shift, true);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
  // The tight crops follow the camera: the same move changes their maps.
  const std::vector<float> c = duel_maps_with_camera_shift(glm::vec3(0.0f), false);
  const std::vector<float> d = duel_maps_with_camera_shift(shift, false);
  ASSERT_EQ(c.size(), d.size());
  EXPECT_FALSE(std::memcmp(c.data(), d.data(), c.size() * sizeof(float)) == 0);
}

std::string frame_error(const char* scene_name, const frame::FrameConfig& o) {
  raster::Renderer r(0);
  try {
    frame::render_frame(scenes::builtin_scene(scene_name), o, r);
  } catch (const frame::FrameError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ViewFollowing, RefusesWhatCannotWork) {
  frame::FrameConfig o;
  o.width = 64;
  o.height = 36;
  o.technique = tech::Technique::cascades;
  o.params["stabilize"] = true;
  o.params["cascade_warp"] = std::string("lispsm");
  // Given as an override (the command line's options): named as the override's field, which the CLI shows as
  // its option.
  EXPECT_EQ(frame_error("duel", o).rfind("params.stabilize: ", 0), 0u) << frame_error("duel", o);
  o.params["cascade_warp"] = std::string("none");
  o.params["view_range"] = std::string("visible");  // a range that follows the camera's view cannot stay still
  EXPECT_EQ(frame_error("duel", o).rfind("params.stabilize: a visible view range", 0), 0u) << frame_error("duel", o);
  o.params.clear();
  o.params["cascades"] = 5.0;
  EXPECT_NE(frame_error("duel", o).find("cascades"), std::string::npos);
  o.params.clear();
  o.technique = tech::Technique::lispsm;
  const std::string spot = frame_error("tutorial-spot", o);
  EXPECT_NE(spot.find("does not serve spot lights"), std::string::npos) << spot;
}

}  // namespace

namespace {

// Exported maps carry every pass: an atlas is one map listing its slices' viewports, labels and matrices;
// separate maps are one file each, still labelled.
TEST(ViewFollowing, ExportedMapsCarryEveryPass) {
  const scenes::Scene scene = scenes::builtin_scene("duel");
  raster::Renderer r(2);
  frame::FrameConfig o;
  o.width = 64;
  o.height = 36;
  o.map_size = 256;
  o.technique = tech::Technique::cascades;
  const auto atlas = frame::export_maps(frame::render_frame(scene, o, r));
  ASSERT_EQ(atlas.size(), 1u);
  EXPECT_EQ(atlas[0].map.width, 512);
  EXPECT_EQ(atlas[0].map.height, 512);
  ASSERT_EQ(atlas[0].map.passes.size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    const auto& p = atlas[0].map.passes[k];
    EXPECT_EQ(p.label, "cascade" + std::to_string(k));
    EXPECT_EQ(p.viewport.x, int(k % 2) * 256);
    EXPECT_EQ(p.viewport.y, int(k / 2) * 256);
    if (k > 0) {
      EXPECT_NE(p.world_to_ndc, atlas[0].map.passes[k - 1].world_to_ndc);
    }
  }
  o.params["map_layout"] = std::string("separate");
  const auto separate = frame::export_maps(frame::render_frame(scene, o, r));
  ASSERT_EQ(separate.size(), 4u);
  EXPECT_EQ(separate[3].name, "light0-sun-3");
  EXPECT_EQ(separate[3].map.passes.at(0).label, "cascade3");
  EXPECT_EQ(separate[3].map.world_to_ndc, atlas[0].map.passes[3].world_to_ndc);
}

}  // namespace

namespace {

// The techniques whose maps are warped (perspective), each with the warp it is asked for: LiSPSM, cascades
// warped by LiSPSM, and the face maps with either projection centre.
const std::pair<tech::Technique, const char*> kWarpedMaps[] = {{tech::Technique::lispsm, ""},
                                                               {tech::Technique::cascades, "lispsm"},
                                                               {tech::Technique::frustum_faces, "exact"},
                                                               {tech::Technique::frustum_faces, "lispsm"}};

void use_warped_map(frame::FrameConfig& o, tech::Technique technique, const char* warp) {
  o.technique = technique;
  o.params.clear();
  if (technique == tech::Technique::cascades) o.params["cascade_warp"] = std::string(warp);
  if (technique == tech::Technique::frustum_faces) o.params["face_warp"] = std::string(warp);
}

// A lone ground plane, lit obliquely and seen from just above it, casts no shadow on itself: every pixel
// renders as with no shadows at all, on each warped map with its default (receiver-plane) slope bias. With no
// bias the same frames show acne, so the check can fail.
TEST(ViewFollowing, ALonePlaneHasNoAcneOnWarpedMaps) {
  scenes::Scene s;
  scenes::Mesh m;
  m.positions = {{-40, 0, -80}, {40, 0, -80}, {40, 0, 10}, {-40, 0, 10}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 2, 1, 0, 3, 2};
  s.meshes.push_back(m);
  s.materials.push_back(scenes::Material{});
  s.instances.push_back(scenes::Instance{});
  s.objects.push_back("ground");
  scenes::Camera cam;
  cam.position = {0, 1.5f, 5};
  cam.target = {0, 0.5f, -20};
  cam.projection = scenes::Perspective{50.0f, std::nullopt, 0.2f, 120.0f};
  s.cameras.push_back(cam);
  scenes::Light sun;
  sun.name = "sun";
  sun.direction = glm::normalize(glm::vec3(0.6f, -0.5f, -0.6f));
  s.lights.push_back(sun);
  raster::Renderer r(2);
  frame::FrameConfig o;
  o.width = 240;
  o.height = 135;
  o.filter = tech::FilterKind::hard;
  o.technique = tech::Technique::none;
  o.exposure = scenes::Exposure{0.0f};  // fixed: a metered exposure would move every row with the shadow
  const frame::Frame unshadowed = frame::render_frame(s, o, r);
  auto differing = [&](const frame::Frame& f) {
    size_t n = 0;
    for (int y = 0; y < f.color.height(); ++y)
      n += std::memcmp(f.color.row8(y), unshadowed.color.row8(y), size_t(f.color.width()) * 4) != 0;
    return n;
  };
  for (const auto& [technique, warp] : kWarpedMaps) {
    use_warped_map(o, technique, warp);
    o.bias = tech::BiasMode::slope;
    EXPECT_EQ(differing(frame::render_frame(s, o, r)), 0u) << tech::to_string(technique) << " " << warp;
    o.bias = tech::BiasMode::none;
    EXPECT_GT(differing(frame::render_frame(s, o, r)), 0u) << tech::to_string(technique) << " " << warp << ", no bias";
  }
}

// The tutorial's sphere (48 × 24 facets) cannot shadow its own lit side: where its facet faces the light, every
// pixel on it reads lit on the warped maps (a factor of at least 0.98: a texel at the far corner of a bilinear
// footprint, weighted a few hundredths, may still compare at the bias's edge, which near the sphere's top is
// the floor of two steps of the cascades' d16), with the default PCF filter and (receiver-plane) slope bias.
// The bias follows the facet's plane, which the map holds, not the smooth shading normal's: with the shading
// normal's plane, the gradient vanished where the normal faces the map's depth axis while the facet's did not,
// and specks of acne showed near the highlight (25 to 46 pixels under 0.98 in these four, factors down to 0.51).
TEST(ViewFollowing, ASphereFacingTheLightHasNoAcneOnWarpedMaps) {
  const scenes::Scene s = scenes::builtin_scene("tutorial");
  const glm::vec3 centre(2.2f, 1.2f, 0.8f), to_light = glm::normalize(glm::vec3(0.5f, 2.0f, 2.0f));
  raster::Renderer r(2);
  frame::FrameConfig o;
  o.width = 1280;
  o.height = 720;
  o.surface_record = true;
  for (const auto& [technique, warp] : kWarpedMaps) {
    use_warped_map(o, technique, warp);
    const frame::Frame f = frame::render_frame(s, o, r);
    ASSERT_TRUE(f.surface.has_value());
    const frame::SurfaceRecord& rec = *f.surface;
    size_t facing = 0, dark = 0;
    for (size_t p = 0; p < rec.pixels(); ++p) {
      // On the sphere, its facet turned towards the light by more than ~12° from grazing.
      if (!rec.covered[p] || std::abs(glm::length(rec.position[p] - centre) - 1.2f) > 0.02f) continue;
      if (glm::dot(rec.normal[p], to_light) < 0.2f || !rec.lit_facing[p * rec.lights]) continue;
      ++facing;
      dark += rec.visibility[p * rec.lights] < 0.98f;
    }
    EXPECT_GT(facing, 8000u) << tech::to_string(technique) << " " << warp;  // the sphere is in view
    EXPECT_EQ(dark, 0u) << tech::to_string(technique) << " " << warp;
  }
}

}  // namespace
