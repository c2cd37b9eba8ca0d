// Per-caster projective shadows through the frame renderer (scenes/frame/frame_projective.*, projective_shaders.h):
// receivers outside every caster frustum are drawn once; the cache rebuilds nothing for a still frame and
// exactly the moved caster's map; multipass and single-pass frames agree within 1/255 (here: exactly); the
// built-in `projective` scene's golden hash is bit-exact at 0, 1 and 2 threads; maps come out as EXR records;
// the offset blur is bit-exact across thread counts; the fade texture with the default table gives the formula's
// frame bit for bit; bad params name their key; the per-pixel surface record holds the product of the maps' factors (analytic
// footprint, the same in both modes and at every thread count).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "scenes/frame/frame.h"
#include "scenes/builtin_scenes.h"
#include "scenes/scene_build.h"
#include "scenes/scene_json.h"
#include "tests/scenes/frame/golden.h"
#include "tests/support.h"

namespace {

int max_difference(const raster::ColorTarget& a, const raster::ColorTarget& b) {
  int d = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width() * 4; ++x) d = std::max(d, std::abs(int(a.row8(y)[x]) - int(b.row8(y)[x])));
  return d;
}

scenes::Scene scene_from(const std::string& json) {
  return scenes::build_scene(scenes::parse_scene_json(json, "test.json"));
}

// Object 0: a floor under the box; object 1: a box caster 1 m above it; object 2: a second floor 20 m away,
// outside the box's frustum; the sun straight down.
const char* kTwoFloors = R"({
  "objects": [
    {"name": "floor", "primitive": {"type": "plane", "size": [6, 6]}, "casts_shadows": false},
    {"name": "box", "primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 1.5, 0]},
     "receives_shadows": false},
    {"name": "far", "primitive": {"type": "plane", "size": [6, 6]}, "transform": {"translate": [20, 0, 0]},
     "casts_shadows": false}
  ],
  "cameras": [{"position": [10, 20, 12], "target": [10, 0, 0]}],
  "lights": [{"type": "directional", "direction": [0, -1, 0],
              "shadow": {"technique": "projective", "map_size": 64}}]
})";

frame::FrameConfig small(int w = 160, int h = 90) {
  frame::FrameConfig o;
  o.width = w;
  o.height = h;
  return o;
}

TEST(ProjectiveFrame, ReceiverOutsideEveryFrustumIsDrawnOnce) {
  const scenes::Scene scene = scene_from(kTwoFloors);
  ASSERT_EQ(scene.instances.size(), 3u);
  raster::Renderer r(testsupport::test_threads());
  for (const char* mode : {"multipass", "single-pass"}) {
    frame::FrameConfig o = small();
    o.params["projective_mode"] = std::string(mode);
    const frame::Frame f = frame::render_frame(scene, o, r);
    const auto& draws = f.stats.projective.receiver_draws;
    ASSERT_EQ(draws.size(), 3u);
    EXPECT_EQ(draws[0], std::string(mode) == "multipass" ? 2u : 1u) << mode;  // the floor under the box
    EXPECT_EQ(draws[1], 1u) << mode;                                            // the caster itself
    EXPECT_EQ(draws[2], 1u) << mode;                                            // the far floor: once, no shadow work
    EXPECT_EQ(f.stats.projective.maps_rebuilt, 1u);
  }
}

// A receiver inside a caster's box (furniture in a room) is not shadowed by that caster's silhouette.
TEST(ProjectiveFrame, ReceiverInsideACastersBoxIsLeftOut) {
  const scenes::Scene scene = scene_from(R"({
    "objects": [
      {"name": "shell", "primitive": {"type": "box", "size": [8, 8, 8]}, "receives_shadows": false,
       "material": "glass"},
      {"name": "inner", "primitive": {"type": "box", "size": [1, 1, 1]}, "casts_shadows": false}
    ],
    "materials": [{"name": "glass", "base_color": [1, 1, 1, 0.5], "double_sided": true}],
    "cameras": [{"position": [0, 2, 3], "target": [0, 0, 0]}],
    "lights": [{"type": "directional", "direction": [0, -1, 0],
                "shadow": {"technique": "projective", "map_size": 32}}]
  })");
  raster::Renderer r(0);
  const frame::Frame f = frame::render_frame(scene, small(), r);
  ASSERT_EQ(f.stats.projective.receiver_draws.size(), 2u);
  EXPECT_EQ(f.stats.projective.receiver_draws[1], 1u);
}

TEST(ProjectiveFrame, CacheRebuildsOnlyWhatMoved) {
  raster::Renderer r(testsupport::test_threads());
  frame::FrameCache cache;
  scenes::Scene scene = scenes::builtin_scene("projective");
  const frame::FrameConfig o = small();
  const frame::Frame f1 = frame::render_frame(scene, o, r, &cache);
  EXPECT_EQ(f1.stats.projective.maps_rebuilt, 5u);
  EXPECT_EQ(f1.stats.projective.maps_reused, 0u);
  const frame::Frame f2 = frame::render_frame(scene, o, r, &cache);
  EXPECT_EQ(f2.stats.projective.maps_rebuilt, 0u);
  EXPECT_EQ(f2.stats.projective.maps_reused, 5u);
  EXPECT_EQ(testsupport::frame_hash(f1.color), testsupport::frame_hash(f2.color));
  // Move one figure (every instance of top-level object 3): exactly its map is rebuilt.
  for (scenes::Instance& inst : scene.instances)
    if (inst.object == 3) inst.transform[3].x += 0.2f;
  const frame::Frame f3 = frame::render_frame(scene, o, r, &cache);
  EXPECT_EQ(f3.stats.projective.maps_rebuilt, 1u);
  EXPECT_EQ(f3.stats.projective.maps_reused, 4u);
  // The scene rebuilt at the same time (a new Scene object, equal content) reuses everything.
  const frame::Frame f4 = frame::render_frame(scenes::builtin_scene("projective"), o, r, &cache);
  EXPECT_EQ(f4.stats.projective.maps_rebuilt, 1u);  // object 3 back in place
  const frame::Frame f5 = frame::render_frame(scenes::builtin_scene("projective", {1.0}), o, r, &cache);
  EXPECT_EQ(f5.stats.projective.maps_rebuilt, 5u);  // everyone walked
}

// The article's "maps only for casters near the view frustum" (caster_reach): with the camera turned away
// (looking up at the sky) no map is built; a skipped caster keeps its cached map for when it is seen again; and
// wherever the camera looks, the frame equals the one with every map built (a skipped shadow cannot be seen).
TEST(ProjectiveFrame, CastersTheCameraCannotSeeGetNoMap) {
  raster::Renderer r(testsupport::test_threads());
  frame::FrameCache cache;
  scenes::Scene scene = scenes::builtin_scene("projective");
  frame::FrameConfig o = small();
  o.params["caster_reach"] = 30.0;
  const frame::Frame facing = frame::render_frame(scene, o, r, &cache);
  EXPECT_EQ(facing.stats.projective.maps_rebuilt, 5u);
  EXPECT_EQ(facing.stats.projective.maps_skipped, 0u);
  scenes::Scene away = scene;
  away.cameras.at(0).target = away.cameras.at(0).position + glm::vec3(0.0f, 40.0f, 14.0f);
  const frame::Frame up = frame::render_frame(away, o, r, &cache);
  EXPECT_EQ(up.stats.projective.maps_rebuilt, 0u);
  EXPECT_EQ(up.stats.projective.maps_reused, 0u);
  EXPECT_EQ(up.stats.projective.maps_skipped, 5u);
  const frame::Frame back = frame::render_frame(scene, o, r, &cache);  // turned back: the kept maps serve
  EXPECT_EQ(back.stats.projective.maps_rebuilt, 0u);
  EXPECT_EQ(back.stats.projective.maps_reused, 5u);
  EXPECT_EQ(testsupport::frame_hash(back.color), testsupport::frame_hash(facing.color));

  frame::FrameConfig every = small();
  size_t skipped = 0;
  for (const glm::vec3 target : {glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(-12.0f, 0.0f, 4.0f),
                                 glm::vec3(14.0f, 0.0f, -10.0f), glm::vec3(0.0f, 12.0f, 30.0f),
                                 glm::vec3(20.0f, 3.0f, 16.0f)}) {
    scenes::Scene s = scene;
    s.cameras.at(0).target = target;
    const frame::Frame near = frame::render_frame(s, o, r);
    const frame::Frame all = frame::render_frame(s, every, r);
    EXPECT_EQ(near.stats.projective.maps_rebuilt + near.stats.projective.maps_skipped, 5u);
    EXPECT_EQ(testsupport::frame_hash(near.color), testsupport::frame_hash(all.color))
        << target.x << " " << target.y << " " << target.z;
    skipped += near.stats.projective.maps_skipped;
  }
  EXPECT_GT(skipped, 0u);
}

TEST(ProjectiveFrame, MultipassEqualsSinglePass) {
  raster::Renderer r(testsupport::test_threads());
  scenes::Scene scene = scenes::builtin_scene("projective", {2.0});
  // Blur and fade on, a grey shade, so every part of the lookup is exercised.
  scene.lights[0].shadow.params["lod_bias"] = 1.5;
  scene.lights[0].shadow.params["fade_start"] = 1.0;
  scene.lights[0].shadow.params["fade_end"] = 4.0;
  scene.lights[0].shadow.params["caster_shade"] = 0.2;
  // Overlapping shadows: a second projective light from the other side.
  scenes::Light second = scene.lights[0];
  second.direction = glm::normalize(glm::vec3(0.7f, -1.0f, -0.4f));
  scene.lights.push_back(second);
  frame::FrameConfig o = small(320, 180);
  o.params["projective_mode"] = std::string("multipass");
  const frame::Frame multi = frame::render_frame(scene, o, r);
  size_t most = 0;
  for (uint32_t d : multi.stats.projective.receiver_draws) most = std::max<size_t>(most, d);
  EXPECT_GE(most, 3u);  // some receiver overlaps two casters or more
  for (int textures : {4, 1}) {
    o.params["projective_mode"] = std::string("single-pass");
    o.params["max_textures"] = double(textures);
    const frame::Frame single = frame::render_frame(scene, o, r);
    const int d = max_difference(multi.color, single.color);
    std::printf("multipass vs single-pass (%d textures): max difference %d/255\n", textures, d);
    EXPECT_LE(d, 1);
  }
  // And the shadows are there: without them the frame differs.
  o.technique = *shading::tech::parse_technique("none");
  o.params.clear();  // projective parameters would reach no light
  EXPECT_GT(max_difference(multi.color, frame::render_frame(scene, o, r).color), 50);
}

// Renders `scene` at 320 × 180 at 0, 1 and 2 threads in both modes and expects one hash; returns that of the
// first frame (0 threads, multipass), dumped as golden `dump_name` when one is given.
uint64_t same_frame_at_every_thread_count(const scenes::Scene& scene, const char* dump_name = nullptr) {
  uint64_t first = 0;
  bool have_first = false;
  for (int threads : {0, 1, 2}) {
    for (const char* mode : {"multipass", "single-pass"}) {
      raster::Renderer r(threads);
      frame::FrameConfig o = small(320, 180);
      o.params["projective_mode"] = std::string(mode);
      const frame::Frame f = frame::render_frame(scene, o, r);
      const uint64_t h = testsupport::frame_hash(f.color);
      if (!have_first) {
        first = h, have_first = true;
        if (dump_name) testsupport::dump_golden(f.color, dump_name);
      }
      EXPECT_EQ(h, first) << "threads " << threads << " " << mode;
    }
  }
  return first;
}

// Golden hash of the built-in `projective` scene at 320 × 180 (time 0, 256² maps per caster).
constexpr uint64_t kGolden = 0x851d7d1461544e47ull;

TEST(ProjectiveFrame, GoldenBuiltinSceneAcrossThreadCounts) {
  const uint64_t first = same_frame_at_every_thread_count(scenes::builtin_scene("projective"), "projective");
  testsupport::expect_golden_hash("projective", first, kGolden);
}

// The article's blur by drawing each map onto itself at an offset (blur_passes): the frame is bit-identical at
// 0, 1 and 2 threads in both modes, and differs from the unblurred one.
TEST(ProjectiveFrame, OffsetBlurIsTheSameAtEveryThreadCount) {
  scenes::Scene scene = scenes::builtin_scene("projective");
  scene.lights[0].shadow.params["blur_passes"] = 2.0;
  scene.lights[0].shadow.params["blur_offset"] = 0.7;
  const uint64_t first = same_frame_at_every_thread_count(scene);
  raster::Renderer r(testsupport::test_threads());
  scene.lights[0].shadow.params.erase("blur_passes");
  scene.lights[0].shadow.params.erase("blur_offset");
  EXPECT_NE(testsupport::frame_hash(frame::render_frame(scene, small(320, 180), r).color), first);
}

// The article's fade through a lookup texture: with the default table (linear) the frame is the formula's bit
// for bit, with blur, a grey shade and two lights, in both modes; another table gives another frame.
TEST(ProjectiveFrame, FadeTextureWithTheDefaultTableIsTheFormulaFrame) {
  raster::Renderer r(testsupport::test_threads());
  scenes::Scene scene = scenes::builtin_scene("projective", {2.0});
  for (auto& [key, value] : std::initializer_list<std::pair<const char*, scenes::TechniqueParam>>{
           {"lod_bias", 1.0}, {"fade_start", 0.5}, {"fade_end", 3.0}, {"caster_shade", 0.2}})
    scene.lights[0].shadow.params[key] = value;
  scenes::Light second = scene.lights[0];
  second.direction = glm::normalize(glm::vec3(0.7f, -1.0f, -0.4f));
  scene.lights.push_back(second);
  for (const char* mode : {"multipass", "single-pass"}) {
    frame::FrameConfig o = small(320, 180);
    o.params["projective_mode"] = std::string(mode);
    const frame::Frame formula = frame::render_frame(scene, o, r);
    o.params["fade_lookup"] = std::string("texture");
    const frame::Frame texture = frame::render_frame(scene, o, r);
    EXPECT_EQ(testsupport::frame_hash(texture.color), testsupport::frame_hash(formula.color)) << mode;
    EXPECT_EQ(max_difference(texture.color, formula.color), 0) << mode;
    o.params["fade_table"] = std::string("smoothstep");
    const frame::Frame smooth = frame::render_frame(scene, o, r);
    EXPECT_GT(max_difference(smooth.color, formula.color), 0) << mode;
  }
}

TEST(ProjectiveFrame, MapsAsExrRecords) {
  raster::Renderer r(0);
  const frame::Frame f = frame::render_frame(scenes::builtin_scene("projective"), small(), r);
  size_t projective = 0;
  const std::vector<frame::NamedMap> maps = frame::export_maps(f);
  for (size_t i = 0; i < maps.size(); ++i) {
    if (maps[i].map.technique != "projective") continue;
    ++projective;
    EXPECT_EQ(maps[i].map.encoding, "caster-mask");
    EXPECT_EQ(maps[i].map.width, 256);
    EXPECT_NE(maps[i].map.world_to_ndc, glm::mat4(1.0f));
    EXPECT_EQ(*std::max_element(maps[i].map.z.begin(), maps[i].map.z.end()), 1.0f);
    EXPECT_EQ(*std::min_element(maps[i].map.z.begin(), maps[i].map.z.end()), 0.0f);
    EXPECT_EQ(maps[i].name.find(' '), std::string::npos) << maps[i].name;
  }
  EXPECT_EQ(projective, 5u);
}

// A light that gives no parameter gets the technique's own defaults: the vocabulary's table and
// ProjectiveSettings agree field by field.
TEST(ProjectiveFrame, TableDefaultsAreTheTechniqueDefaults) {
  shading::tech::ShadowConfig c;
  c.technique = shading::tech::Technique::projective;
  c.map_size = int(shading::tech::info(c.technique).map_size);
  const shading::tech::ProjectiveSettings p = frame::resolve_projective(c), d;
  EXPECT_EQ(p.map_size, d.map_size);
  EXPECT_EQ(p.mode, d.mode);
  EXPECT_EQ(p.caster_shade, d.caster_shade);
  EXPECT_EQ(p.lod_bias, d.lod_bias);
  EXPECT_EQ(p.fade_start, d.fade_start);
  EXPECT_EQ(p.fade_end, d.fade_end);
  EXPECT_EQ(p.blur_passes, d.blur_passes);
  EXPECT_EQ(p.blur_offset, d.blur_offset);
  EXPECT_EQ(p.fade_lookup, d.fade_lookup);
  EXPECT_EQ(p.fade_table, d.fade_table);
  EXPECT_EQ(p.decimate, d.decimate);
  EXPECT_EQ(p.max_textures, d.max_textures);
}

TEST(ProjectiveFrame, BadParamsNameTheirKey) {
  raster::Renderer r(0);
  auto expect_bad = [&](const char* key, scenes::TechniqueParam value, const std::string& where) {
    scenes::Scene scene = scene_from(kTwoFloors);
    scene.lights[0].shadow.params[key] = value;
    try {
      frame::render_frame(scene, small(), r);
      ADD_FAILURE() << key << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
    }
  };
  expect_bad("caster_shade", 2.0, "lights[0].shadow.params.caster_shade: ");
  expect_bad("caster_shade", std::string("dark"), "lights[0].shadow.params.caster_shade: ");
  expect_bad("lod_bias", -1.0, "lights[0].shadow.params.lod_bias: ");
  expect_bad("fade_end", -1.0, "lights[0].shadow.params.fade_end: ");
  expect_bad("max_textures", 2.5, "lights[0].shadow.params.max_textures: ");
  expect_bad("projective_mode", std::string("twice"), "lights[0].shadow.params.projective_mode: ");
  expect_bad("decimate", 1.0, "lights[0].shadow.params.decimate: ");
  expect_bad("blur_passes", 17.0, "lights[0].shadow.params.blur_passes: ");
  expect_bad("blur_passes", 1.5, "lights[0].shadow.params.blur_passes: ");
  expect_bad("blur_offset", 0.0, "lights[0].shadow.params.blur_offset: ");
  expect_bad("blur_offset", 1.5, "lights[0].shadow.params.blur_offset: ");
  expect_bad("fade_lookup", std::string("curve"), "lights[0].shadow.params.fade_lookup: ");
  expect_bad("fade_lookup", std::string("texture"), "lights[0].shadow.params.fade_lookup: ");  // no fade range
  expect_bad("fade_table", std::string("1,2"), "lights[0].shadow.params.fade_table: ");
  expect_bad("fade_table", std::string("steep"), "lights[0].shadow.params.fade_table: ");
  expect_bad("fade_table", 0.5, "lights[0].shadow.params.fade_table: ");
  // Settings that would do nothing: a table without the texture lookup, an offset without passes.
  expect_bad("fade_table", std::string("1,1"), "lights[0].shadow.params.fade_table: ");
  expect_bad("blur_offset", 0.5, "lights[0].shadow.params.blur_offset: ");
  expect_bad("fade_start", 1.0, "lights[0].shadow.params.fade_start: ");  // no fade_end: it never fades
  expect_bad("max_textures", 2.0, "lights[0].shadow.params.max_textures: ");  // multipass applies one at a time
  {  // fade_end 0, the default written out, means no fade, as left out
    scenes::Scene written = scene_from(kTwoFloors);
    written.lights[0].shadow.params["fade_end"] = 0.0;
    EXPECT_EQ(max_difference(frame::render_frame(written, small(), r).color,
                             frame::render_frame(scene_from(kTwoFloors), small(), r).color),
              0);
  }
  {  // one mode serves the whole frame: a second projective light asking for another is refused, not overruled
    scenes::Scene two = scene_from(kTwoFloors);
    two.lights.push_back(two.lights[0]);
    two.lights[1].shadow.params["projective_mode"] = std::string("single-pass");
    try {
      frame::render_frame(two, small(), r);
      ADD_FAILURE() << "two modes accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("lights[1].shadow.params.projective_mode: differs", 0), 0u) << e.what();
    }
  }
  scenes::Scene scene = scene_from(kTwoFloors);
  frame::FrameConfig o = small();
  o.params["projective_mode"] = std::string("sometimes");
  EXPECT_THROW(frame::render_frame(scene, o, r), std::invalid_argument);
}

// The surface record of a projective light: the product of the factors the receiver passes multiplied in. The
// box (1 m, from 1 m to 2 m above the floor) under a sun along (1, −1, 0) shadows exactly the floor's rectangle
// 0.5 < x < 2.5, |z| < 0.5 (a point at height y lands y further along x); pixels well inside record 0, pixels well
// outside 1, in both modes and at 0, 1, 2 threads.
TEST(ProjectiveFrame, SurfaceRecordHoldsTheMapsFactors) {
  scenes::Scene scene = scene_from(kTwoFloors);
  scene.cameras.at(0).position = glm::vec3(0.0f, 8.0f, 4.0f);
  scene.cameras.at(0).target = glm::vec3(0.0f);
  scene.lights.at(0).direction = glm::vec3(1.0f, -1.0f, 0.0f);
  std::vector<float> first;
  for (int threads : {0, 1, 2}) {
    for (const char* mode : {"multipass", "single-pass"}) {
      raster::Renderer r(threads);
      frame::FrameConfig o = small(200, 150);
      o.surface_record = true;
      o.params["projective_mode"] = std::string(mode);
      const frame::Frame f = frame::render_frame(scene, o, r);
      ASSERT_TRUE(f.surface);
      const frame::SurfaceRecord& rec = *f.surface;
      size_t inside = 0, outside = 0, wrong = 0;
      for (size_t p = 0; p < rec.pixels(); ++p) {
        const glm::vec3 w = rec.position[p];
        if (!rec.covered[p] || std::fabs(w.y) > 1e-3f || !rec.lit_facing[p]) continue;  // floor pixels only
        if (std::fabs(w.x - 1.5f) < 0.9f && std::fabs(w.z) < 0.4f) {
          ++inside;
          wrong += rec.visibility[p] != 0.0f;
        } else if (std::fabs(w.x - 1.5f) > 1.1f || std::fabs(w.z) > 0.6f) {
          ++outside;
          wrong += rec.visibility[p] != 1.0f;
        }
      }
      EXPECT_GT(inside, 500u) << mode;
      EXPECT_GT(outside, 5000u) << mode;
      EXPECT_EQ(wrong, 0u) << mode << " threads " << threads;
      if (first.empty()) first = rec.visibility;
      EXPECT_TRUE(rec.visibility == first) << mode << " threads " << threads;
    }
  }
}

}  // namespace
