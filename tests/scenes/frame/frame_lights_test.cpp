// Per-light shadow settings in the frame renderer (scenes/frame/frame_lights.h): every light is read with its own
// filter, and the command-line value overrides reach the technique layer or are refused naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "scenes/frame/frame.h"
#include "scenes/frame/frame_lights.h"
#include "scenes/builtin_scenes.h"
#include "tests/scenes/frame/floor_scene.h"
#include "tests/support.h"

namespace {

size_t pixels_differing(const raster::ColorTarget& a, const raster::ColorTarget& b) {
  size_t n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) n += a.read(x, y) != b.read(x, y);
  return n;
}

// The tutorial's sun plus the tutorial-spot scene's spot, both casting shadows.
scenes::Scene two_lights() {
  scenes::Scene s = scenes::builtin_scene("tutorial");
  s.lights.push_back(scenes::builtin_scene("tutorial-spot").lights.at(0));
  return s;
}

}  // namespace

// If one filter were used for the whole frame (the first light's or the last's), the mixed frame would equal one
// of the uniform frames. It must differ from all three other assignments.
TEST(FrameLights, EachLightIsReadWithItsOwnFilter) {
  raster::Renderer renderer(testsupport::test_threads());
  scenes::Scene scene = two_lights();
  frame::FrameConfig opt;
  opt.width = 192, opt.height = 108;
  opt.map_size = 256;
  auto render = [&](scenes::ShadowFilter a, scenes::ShadowFilter b) {
    scene.lights[0].shadow.filter = a;
    scene.lights[1].shadow.filter = b;
    frame::Frame f = frame::render_frame(scene, opt, renderer);
    EXPECT_EQ(frame::export_maps(f).size(), 2u);
    return std::move(f.color);
  };
  using F = scenes::ShadowFilter;
  const raster::ColorTarget hh = render(F::hard, F::hard), hp = render(F::hard, F::pcf),
                            ph = render(F::pcf, F::hard), pp = render(F::pcf, F::pcf);
  EXPECT_GT(pixels_differing(hp, hh), 0u);
  EXPECT_GT(pixels_differing(hp, pp), 0u);
  EXPECT_GT(pixels_differing(hp, ph), 0u);
  EXPECT_GT(pixels_differing(ph, hh), 0u);
}

TEST(FrameLights, OverridesReachTheTechniqueSettings) {
  const scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  frame::FrameConfig o;
  o.bias_constant = 0.02f, o.bias_slope = 0.003f, o.bias_slope_max = 0.05f;
  o.offset_factor = -2.0f, o.offset_units = 8.0f, o.normal_offset = 0.1f;
  o.poisson_spread = 1.0f / 350.0f;
  o.params["stratify"] = std::string("world");
  o.filter = scenes::ShadowFilter::stratified;  // the filter world seeds apply to
  o.params["fit"] = std::string("fixed");
  const frame::ResolvedLight r = frame::resolve_light(sun, 0, o);
  EXPECT_EQ(r.config.bias.constant, 0.02f);
  EXPECT_EQ(r.config.bias.slope, 0.003f);
  EXPECT_EQ(r.config.bias.slope_max, 0.05f);
  EXPECT_EQ(r.config.bias.offset_factor, -2.0f);
  EXPECT_EQ(r.config.bias.offset_units, 8.0f);
  EXPECT_EQ(r.config.bias.normal_offset, 0.1f);
  EXPECT_EQ(r.config.filter_params.spread, 1.0f / 350.0f);
  EXPECT_TRUE(r.config.filter_params.stratify_world);
  EXPECT_EQ(std::get<std::string>(r.config.params.at("fit")), "fixed");
  // Unset options keep the light's own values.
  const frame::ResolvedLight d = frame::resolve_light(sun, 0, frame::FrameConfig{});
  EXPECT_EQ(d.config.bias.constant, sun.shadow.bias.constant);
  EXPECT_EQ(d.config.filter_params.spread, sun.shadow.poisson_spread);
  EXPECT_FALSE(d.config.filter_params.stratify_world);
}

// A technique override brings its own map size and depth format to a light that holds its technique's defaults,
// and leaves a light's own values alone.
TEST(FrameLights, ATechniqueOverrideBringsItsDefaultMap) {
  scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  sun.shadow.map_size = scenes::default_map_size(sun.shadow.technique);  // 1024, d16: the classic map's defaults
  ASSERT_EQ(sun.shadow.depth_format, raster::DepthFormat::d16);
  frame::FrameConfig o;
  o.technique = scenes::ShadowTechnique::lispsm;
  frame::ResolvedLight r = frame::resolve_light(sun, 0, o);
  EXPECT_EQ(r.config.map_size, 2048);
  EXPECT_EQ(r.config.depth_format, raster::DepthFormat::d24);
  o.technique = scenes::ShadowTechnique::esm;
  r = frame::resolve_light(sun, 0, o);
  EXPECT_EQ(r.config.map_size, 1024);
  EXPECT_EQ(r.config.depth_format, raster::DepthFormat::d32f);
  // The light's own values stay; the command line's own override both.
  sun.shadow.map_size = 512, sun.shadow.depth_format = raster::DepthFormat::d24;
  r = frame::resolve_light(sun, 0, o);
  EXPECT_EQ(r.config.map_size, 512);
  EXPECT_EQ(r.config.depth_format, raster::DepthFormat::d24);
  o.map_size = 256, o.depth_format = raster::DepthFormat::d16;
  r = frame::resolve_light(sun, 0, o);
  EXPECT_EQ(r.config.map_size, 256);
  EXPECT_EQ(r.config.depth_format, raster::DepthFormat::d16);
  // The light's own technique named again changes nothing.
  o = {};
  o.technique = scenes::ShadowTechnique::shadowmap;
  EXPECT_EQ(frame::resolve_light(sun, 0, o).config.depth_format, raster::DepthFormat::d24);
}

TEST(FrameLights, BadOverridesNameTheField) {
  const scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  auto message = [&](auto set) {
    frame::FrameConfig o;
    set(o);
    try {
      frame::resolve_light(sun, 0, o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.poisson_spread = 0.0f; }).rfind("poisson_spread: ", 0), 0u);
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.poisson_spread = 1e30f; }),
            "poisson_spread: 1e+30 is above 1, the whole map's width");
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.bias_constant = -0.5f; }),
            "bias.constant: -0.5 must be a finite number of 0 or more");
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.bias_constant = -0.1f; }).rfind("bias.constant: ", 0), 0u);
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.bias_slope = NAN; }).rfind("bias.slope: ", 0), 0u);
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.offset_units = INFINITY; }).rfind("bias.offset_units: ", 0), 0u);
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.params["stratify"] = std::string("diagonal"); }).rfind("lights[0].shadow.params.stratify: ", 0), 0u);
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.offset_factor = -3.0f; }), "no error");  // signed is fine
  // Poisson settings beside a filter without Poisson taps would do nothing (the sun reads with pcf): errors,
  // named as the command line's fields; under a --filter of the command line the light's own are dropped.
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.params["stratify"] = std::string("world"); }),
            "params.stratify: world seeds the stratified and rotated filters, not pcf");
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.params["pcf_taps"] = true; }),
            "params.pcf_taps: makes the taps of the poisson, stratified, rotated and early-bail filters PCF lookups, "
            "not pcf");
  scenes::Light poisson_sun = sun;
  poisson_sun.shadow.filter = scenes::ShadowFilter::poisson;
  poisson_sun.shadow.params["pcf_taps"] = true;
  frame::FrameConfig hard;
  hard.filter = scenes::ShadowFilter::hard;
  EXPECT_FALSE(frame::resolve_light(poisson_sun, 0, hard).config.filter_params.pcf_taps);
  EXPECT_TRUE(frame::resolve_light(poisson_sun, 0, frame::FrameConfig{}).config.filter_params.pcf_taps);
  // The tutorial's arithmetic is a variant of the Poisson filters only (the tutorial's sun reads with pcf); an
  // override is named as the command line's field, which the CLI shows as its option.
  EXPECT_EQ(message([](frame::FrameConfig& o) { o.params["poisson_variant"] = std::string("tutorial"); }),
            "params.poisson_variant: tutorial is a variant of the poisson, stratified and rotated filters, not pcf");
  EXPECT_EQ(message([](frame::FrameConfig& o) {
              o.filter = shading::tech::FilterKind::stratified;
              o.params["poisson_variant"] = std::string("tutorial");
            }),
            "no error");
}

TEST(FrameLights, TutorialPoissonVariantReachesTheFilter) {
  const scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  frame::FrameConfig o;
  o.filter = shading::tech::FilterKind::rotated;
  EXPECT_FALSE(frame::resolve_light(sun, 0, o).config.filter_params.tutorial);
  o.params["poisson_variant"] = std::string("tutorial");
  EXPECT_TRUE(frame::resolve_light(sun, 0, o).config.filter_params.tutorial);
}

// Issue 23: a bad value of the light's own (not overridden) was named as the override's field, which the CLI
// shows as its option; it is named as the light's field.
TEST(FrameLights, BadLightValuesNameTheLightsField) {
  scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  sun.shadow.bias.slope_max = -1.0f;
  try {
    frame::resolve_light(sun, 2, frame::FrameConfig{});
    FAIL() << "no error";
  } catch (const frame::FrameError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("lights[2].shadow.bias.slope_max: ", 0), 0u) << e.what();
  }
  frame::FrameConfig o;
  o.bias_slope_max = 0.02f;  // the override replaces the bad value
  EXPECT_NO_THROW(frame::resolve_light(sun, 2, o));
}

// Issue 23: map sides a technique cannot hold are refused before anything is allocated, named where they came
// from (the override, shown by the CLI as --shadow-size, or the light's own setting).
TEST(FrameLights, MapSidesATechniqueCannotHoldAreRefusedEarly) {
  const scenes::Scene pyramid = scenes::builtin_scene("pyramid");
  scenes::Light lamp = pyramid.lights.at(0);
  auto message = [&](const scenes::Light& l, const frame::FrameConfig& o) {
    try {
      frame::resolve_light(l, 0, o);
    } catch (const frame::FrameError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  frame::FrameConfig o;
  o.technique = shading::tech::Technique::cube;
  o.map_size = 16384;
  EXPECT_EQ(message(lamp, o), "map_size: 16384 is outside 16..5461 for technique cube (its maps share one target of "
                              "at most 16384 texels a side)");
  o.map_size = 5461;
  EXPECT_EQ(message(lamp, o), "no error");
  lamp.shadow.technique = shading::tech::Technique::pyramid;
  lamp.shadow.map_size = 63;
  EXPECT_EQ(message(lamp, frame::FrameConfig{}),
            "lights[0].shadow.map_size: the pyramid map side 63 must be even (two halves per axis)");
}

// A point-like light's ambient is its flux, reflected once at albedo ½, over the surface of the scene's box:
// ½ · Φ / A. A 10 × 3 × 10 m box has A = 2(30 + 30 + 100) = 320 m².
TEST(FrameLights, AmbientIsHalfTheFluxOverTheBoundsSurface) {
  const scenes::Aabb box{{-5.0f, 0.0f, -5.0f}, {5.0f, 3.0f, 5.0f}};
  scenes::Light l;
  l.intensity = 1000.0f;
  l.type = scenes::LightType::point;
  EXPECT_NEAR(frame::ambient_illuminance(l, box), 0.5 * 4.0 * M_PI * 1000.0 / 320.0, 1e-3);
  l.type = scenes::LightType::hemispherical;
  EXPECT_NEAR(frame::ambient_illuminance(l, box), 0.5 * 2.0 * M_PI * 1000.0 / 320.0, 1e-3);
  l.type = scenes::LightType::spot;
  l.outer_cone_deg = 60.0f;  // solid angle 2π(1 − cos 60°) = π
  EXPECT_NEAR(frame::ambient_illuminance(l, box), 0.5 * M_PI * 1000.0 / 320.0, 1e-3);
  l.type = scenes::LightType::directional;  // its ambient is Material::ambient of its lux, not this
  EXPECT_EQ(frame::ambient_illuminance(l, box), 0.0f);
  l.type = scenes::LightType::point;
  EXPECT_EQ(frame::ambient_illuminance(l, scenes::Aabb{}), 0.0f);  // nothing in the scene
}

// In a frame the ambient is the same everywhere: a floor under a spot that points away from it (no direct light
// on it) shows albedo / π · E_a at every pixel, near the lamp and far from it alike.
TEST(FrameLights, AmbientOfASpotIsUniformOverTheFloor) {
  scenes::Scene s = testsupport::floor_seen_from_above({0.5f, 0.5f, 0.5f});
  scenes::Light spot;
  spot.type = scenes::LightType::spot;
  spot.position = {-15, 1, -5};
  spot.direction = {0, 1, 0};  // up, away from the floor
  spot.intensity = 5000.0f;
  spot.outer_cone_deg = 30.0f;
  spot.shadow.technique = scenes::ShadowTechnique::none;
  s.lights.push_back(spot);
  raster::Renderer renderer(testsupport::test_threads());
  frame::FrameConfig o;
  o.width = 64, o.height = 36;
  const frame::Frame f = frame::render_frame(s, o, renderer);
  // The floor is flat (y = 0): A = 2 · 40 · 40.
  const double expected = 0.5 / M_PI * 0.5 * 2.0 * M_PI * (1.0 - std::cos(M_PI / 6.0)) * 5000.0 / 3200.0;
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) {
      const glm::vec4 p = f.radiance.read(x, y);
      ASSERT_EQ(p.a, 1.0f) << x << ", " << y;
      ASSERT_NEAR(p.r, expected, expected * 1e-5) << x << ", " << y;
    }
}

// A moment-map light over a receiver that casts nothing (the projective scene's terrain) is warned about, naming
// the light and the object; a classic map, or the same light once the terrain casts, is not. cube and cascades
// warn only with their `moments` parameter.
TEST(FrameLights, MomentMapsWarnOfReceiversMissingFromTheMap) {
  scenes::Scene s = scenes::builtin_scene("projective");
  ASSERT_FALSE(s.lights.empty());
  ASSERT_EQ(s.objects.at(0), "terrain");
  auto warning = [&](shading::tech::Technique t, std::map<std::string, shading::tech::ParamValue> params = {}) {
    frame::FrameConfig o;
    o.technique = t;
    o.params = std::move(params);
    return frame::moment_receiver_warning(frame::resolve_light(s.lights[0], 0, o), 0, s);
  };
  using shading::tech::Technique;
  for (Technique t : {Technique::esm, Technique::vsm, Technique::evsm2, Technique::evsm4}) {
    const std::optional<std::string> w = warning(t);
    ASSERT_TRUE(w) << shading::tech::to_string(t);
    EXPECT_EQ(w->rfind("lights[0] (" + s.lights[0].name + "): " + std::string(shading::tech::to_string(t)) +
                           " reads its map's moments around each receiver, and objects[0] (terrain) receives shadows",
                       0),
              0u)
        << *w;
  }
  EXPECT_FALSE(warning(Technique::shadowmap));
  EXPECT_FALSE(warning(Technique::pcss));
  EXPECT_FALSE(warning(Technique::cascades));
  EXPECT_TRUE(warning(Technique::cascades, {{"moments", std::string("vsm")}}));
  for (scenes::Instance& inst : s.instances) inst.casts_shadows = true;
  EXPECT_FALSE(warning(Technique::esm));
  // Two objects: both named, in the plural.
  for (scenes::Instance& inst : s.instances) {
    inst.casts_shadows = inst.object > 1;
    inst.receives_shadows = true;
  }
  const std::optional<std::string> two = warning(Technique::vsm);
  ASSERT_TRUE(two);
  EXPECT_NE(two->find("objects[0] (terrain), objects[1]"), std::string::npos) << *two;
  EXPECT_NE(two->find("receive shadows without casting: they are not in the map"), std::string::npos) << *two;
}
