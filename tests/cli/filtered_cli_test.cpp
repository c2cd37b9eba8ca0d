// The filterable maps and PCSS from the command line: each renders, and a bad setting — an exponent that
// overflows 32-bit float storage, a negative light size, a blur radius out of range, a parameter in a scene file
// out of range — is refused with one line naming the option or field, exit 2 and no output file.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

TEST(CliFiltered, EachTechniqueRendersTheTutorial) {
  const auto dir = testsupport::temp_dir("cli_filtered_render");
  for (const char* t : {"esm", "vsm", "evsm2", "evsm4", "pcss"}) {
    const testsupport::Outcome r = testsupport::shadowlab(
        dir, std::string("render tutorial --size 64x36 --shadow-size 128 --threads 2 --out f.png --technique ") + t);
    EXPECT_EQ(r.code, 0) << t << ": " << r.err;
    EXPECT_EQ(r.err, "") << t;  // every object of the room casts: no warning
    EXPECT_TRUE(std::filesystem::exists(dir / "f.png")) << t;
    std::filesystem::remove(dir / "f.png");
  }
}

// A bad `moments` setting on a light picked by --light is named by the light's place in the file, with the
// file, before anything renders (the frame's warning check leaves it to the technique's planning).
TEST(CliFiltered, BadMomentSettingsOfAPickedLightNameItsField) {
  const auto dir = testsupport::temp_dir("cli_filtered_moments_light");
  std::ofstream(dir / "two.json") << R"({"objects": [{"primitive": {"type": "plane", "size": [8, 8]}},
      {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}],
    "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3]},
               {"type": "directional", "direction": [0.4, -1, -0.3],
                "shadow": {"technique": "cascades", "filter": "poisson", "params": {"moments": "vsm"}}}]})";
  const testsupport::Outcome r = testsupport::shadowlab(dir, "render two.json --light 1 --size 32x18 --out f.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("shadowlab: error: two.json: lights[1].shadow.filter: poisson is not used with moments = vsm", 0), 0u)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "f.png"));
}

// The projective scene's terrain only receives: a moment map misses it and its figures' shadows vanish, which
// the run says once (not once per frame), and still renders; with the classic map it says nothing.
TEST(CliFiltered, MomentMapsOverReceiversThatCastNothingAreWarnedOnce) {
  const auto dir = testsupport::temp_dir("cli_filtered_warn");
  const testsupport::Outcome r = testsupport::shadowlab(
      dir, "render projective --size 64x36 --shadow-size 128 --frames 2 --animate --technique esm --out f.png");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, ::testing::MatchesRegex("shadowlab: warning: projective: lights\\[0\\] \\([a-z]+\\): esm reads its "
                                             "map's moments around each receiver, and objects\\[0\\] \\(terrain\\) "
                                             "receives shadows without casting[^\n]+\n"));
  EXPECT_TRUE(std::filesystem::exists(dir / "f.png"));
  const testsupport::Outcome classic =
      testsupport::shadowlab(dir, "render projective --size 64x36 --shadow-size 128 --technique shadowmap --out g.png");
  EXPECT_EQ(classic.code, 0) << classic.err;
  EXPECT_EQ(classic.err, "");
}

// Under --light the warning names the light by its place in the file, as an error would.
TEST(CliFiltered, MomentWarningOfAPickedLightNamesItsPlaceInTheFile) {
  const auto dir = testsupport::temp_dir("cli_filtered_warn_light");
  std::ofstream(dir / "two.json") << R"({"objects": [{"name": "floor", "primitive": {"type": "plane", "size": [8, 8]},
        "casts_shadows": false},
      {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}],
    "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3]},
               {"name": "key", "type": "directional", "direction": [0.4, -1, -0.3], "shadow": {"technique": "vsm"}}]})";
  const testsupport::Outcome r = testsupport::shadowlab(dir, "render two.json --light 1 --size 32x18 --out f.png");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("shadowlab: warning: two.json: lights[1] (key): vsm reads its map's moments", 0), 0u) << r.err;
}

TEST(CliFiltered, PcssOnAPointLightsCubeMap) {
  const auto dir = testsupport::temp_dir("cli_filtered_cube_pcss");
  const testsupport::Outcome r = testsupport::shadowlab(
      dir, "render paraboloid --size 64x36 --shadow-size 128 --threads 2 --out f.png --technique cube "
           "--soft-shadows pcss --light-radius 0.2");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "f.png"));
  const std::string cube = "render paraboloid --size 32x18 --out o.png --technique cube ";
  // The size alone would do nothing; a filter PCSS replaces; the paraboloid map has no PCSS.
  testsupport::expect_bad_run(dir, cube + "--light-radius 0.2", "--light-radius", "o.png");
  testsupport::expect_bad_run(dir, cube + "--soft-shadows pcss --filter poisson", "lights[0].shadow.filter", "o.png");
  testsupport::expect_bad_run(dir, "render paraboloid --size 32x18 --out o.png --technique paraboloid --soft-shadows pcss",
                              "--soft-shadows", "o.png");
}

TEST(CliFiltered, BadSettingsNameTheirOption) {
  const auto dir = testsupport::temp_dir("cli_filtered_bad");
  const std::string render = "render tutorial --size 32x18 --out o.png ";
  testsupport::expect_bad_run(dir, render + "--technique esm --esm-c 100", "--esm-c", "o.png");
  const testsupport::Outcome r = testsupport::shadowlab(dir, render + "--technique esm --esm-c 100");
  EXPECT_THAT(r.err, ::testing::HasSubstr("overflows 32-bit float storage")) << r.err;
  testsupport::expect_bad_run(dir, render + "--technique evsm4 --evsm-positive 50", "--evsm-positive", "o.png");
  testsupport::expect_bad_run(dir, render + "--technique pcss --light-angle -1", "--light-angle", "o.png");
  testsupport::expect_bad_run(dir, "render tutorial-spot --size 32x18 --out o.png --technique pcss --light-radius -0.5",
                              "--light-radius", "o.png");
  testsupport::expect_bad_run(dir, render + "--technique vsm --blur-radius 17", "--blur-radius", "o.png");
  testsupport::expect_bad_run(dir, render + "--technique vsm --light-bleed 1", "--light-bleed", "o.png");
  // A parameter no light's technique takes.
  testsupport::expect_bad_run(dir, render + "--technique shadowmap --esm-c 40", "--esm-c", "o.png");
}

TEST(CliFiltered, SceneFileExponentOutOfRangeNamesTheField) {
  const auto dir = testsupport::temp_dir("cli_filtered_scene");
  std::ofstream(dir / "s.json") << R"({"version": 1, "name": "s", "objects": [
    {"name": "floor", "primitive": {"type": "box", "size": [4, 0.5, 4]}}],
  "cameras": [{"position": [3, 4, 5], "target": [0, 0, 0], "perspective": {"fovy": 50, "near": 0.5, "far": 60}}],
  "lights": [{"name": "sun", "type": "directional", "to_light": [0.5, 2, 1],
              "shadow": {"technique": "esm", "params": {"esm_c": 90}}}]})";
  testsupport::expect_bad_run(dir, "render s.json --size 32x18 --out o.png", "s.json", "o.png");
  const testsupport::Outcome r = testsupport::shadowlab(dir, "render s.json --size 32x18 --out o.png");
  EXPECT_THAT(r.err, ::testing::HasSubstr("lights[0].shadow.params.esm_c")) << r.err;
}

}  // namespace
