// When a declared parameter does nothing (shading/techniques/param_use.h): every rule, read and unread, and the
// frame's refusals of a light's own unread key and of an override no light reads.
#include <gtest/gtest.h>

#include <string>

#include "scenes/builtin_scenes.h"
#include "scenes/frame/frame.h"
#include "scenes/frame/frame_lights.h"
#include "shading/techniques/param_use.h"

namespace {

namespace tech = shading::tech;
using tech::LightType;

tech::ShadowConfig config(tech::Technique t, std::map<std::string, tech::ParamValue> params = {}) {
  tech::ShadowConfig c;
  c.technique = t;
  c.params = std::move(params);
  return c;
}

bool read(const tech::ShadowConfig& c, LightType light, const char* key) { return !tech::unread_param(c, light, key); }

}  // namespace

TEST(ParamUse, PcssReadsTheSizeOfItsLightType) {
  const tech::ShadowConfig c = config(tech::Technique::pcss);
  EXPECT_TRUE(read(c, LightType::directional, "light_angle"));
  EXPECT_FALSE(read(c, LightType::directional, "light_radius"));
  EXPECT_TRUE(read(c, LightType::spot, "light_radius"));
  EXPECT_FALSE(read(c, LightType::spot, "light_angle"));
  EXPECT_EQ(*tech::unread_param(c, LightType::spot, "light_angle"),
            "is a directional light's size; a spot light's is light_radius (metres)");
}

TEST(ParamUse, SoftShadowSizesNeedPcss) {
  EXPECT_FALSE(read(config(tech::Technique::cascades), LightType::directional, "light_angle"));
  EXPECT_TRUE(read(config(tech::Technique::cascades, {{"soft_shadows", std::string("pcss")}}), LightType::directional,
                   "light_angle"));
  EXPECT_FALSE(read(config(tech::Technique::cube), LightType::point, "light_radius"));
  EXPECT_TRUE(read(config(tech::Technique::cube, {{"soft_shadows", std::string("pcss")}}), LightType::point,
                   "light_radius"));
}

TEST(ParamUse, MomentKeysFollowTheKind) {
  const char* keys[] = {"blur_radius",   "moment_mips",   "esm_c",         "light_bleed",
                        "min_variance",  "evsm_positive", "evsm_negative", "evsm_min_variance"};
  // Which of keys[] each kind reads, in order.
  const std::pair<const char*, std::string> kinds[] = {{"none", "00000000"},  {"esm", "11100000"},
                                                       {"vsm", "11011000"},   {"evsm2", "11010101"},
                                                       {"evsm4", "11010111"}};
  for (const tech::Technique t : {tech::Technique::cascades, tech::Technique::cube})
    for (const auto& [kind, expected] : kinds) {
      const tech::ShadowConfig c = config(t, {{"moments", std::string(kind)}});
      std::string got;
      for (const char* key : keys) got += read(c, LightType::directional, key) ? '1' : '0';
      EXPECT_EQ(got, expected) << tech::to_string(t) << " moments = " << kind;
    }
  // The filterable techniques themselves read theirs whatever the light.
  EXPECT_TRUE(read(config(tech::Technique::esm), LightType::spot, "blur_radius"));
}

TEST(ParamUse, TheClassicFitIsForDirectionalLights) {
  const tech::ShadowConfig tutorial = config(tech::Technique::shadowmap, {{"fit", std::string("tutorial")}});
  EXPECT_TRUE(read(tutorial, LightType::directional, "fit_cutoff"));
  EXPECT_FALSE(read(tutorial, LightType::spot, "fit"));
  EXPECT_FALSE(read(tutorial, LightType::spot, "fit_cutoff"));
  EXPECT_FALSE(read(config(tech::Technique::shadowmap), LightType::directional, "fit_smoothing"));
  EXPECT_TRUE(read(config(tech::Technique::shadowmap), LightType::directional, "fit"));
}

TEST(ParamUse, TheSplitPlaneIsAPointLights) {
  const tech::ShadowConfig c = config(tech::Technique::paraboloid, {{"split_plane", std::string("y")}});
  EXPECT_TRUE(read(c, LightType::point, "split_plane"));
  EXPECT_FALSE(read(c, LightType::hemispherical, "split_plane"));
}

// A light's own unread key is refused where the scene gave it; an override, when no light of the frame reads it.
TEST(ParamUse, FramesRefuseSettingsThatDoNothing) {
  scenes::Light spot = scenes::builtin_scene("tutorial-spot").lights.at(0);
  spot.shadow.technique = tech::Technique::pcss;
  spot.shadow.params["light_angle"] = 2.0;
  try {
    frame::resolve_light(spot, 3, frame::FrameConfig{});
    FAIL() << "a spot light's light_angle was taken";
  } catch (const frame::FrameError& e) {
    EXPECT_EQ(std::string(e.what()),
              "lights[3].shadow.params.light_angle: is a directional light's size; a spot light's is light_radius "
              "(metres)");
  }
  spot.shadow.params.clear();
  EXPECT_NO_THROW(frame::resolve_light(spot, 0, frame::FrameConfig{}));

  raster::Renderer renderer(0);
  scenes::Scene scene = scenes::builtin_scene("tutorial-spot");
  scene.lights = {spot};
  frame::FrameConfig o;
  o.width = 32, o.height = 18;
  o.params["light_angle"] = 2.0;  // --light-angle with pcss on the spot only
  try {
    frame::render_frame(scene, o, renderer);
    FAIL() << "an override no light reads was taken";
  } catch (const frame::FrameError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("params.light_angle: is a directional light's size", 0), 0u) << e.what();
  }
  // With a directional light beside it that reads it, the override is taken.
  scenes::Light sun = scenes::builtin_scene("tutorial").lights.at(0);
  sun.shadow.technique = tech::Technique::pcss;
  sun.shadow.map_size = 256;
  scene.lights.push_back(sun);
  scene.lights[0].shadow.map_size = 256;
  EXPECT_NO_THROW(frame::render_frame(scene, o, renderer));
}
