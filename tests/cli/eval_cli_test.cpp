// End-to-end tests of `shadowlab eval` and `shadowlab render --aov`: the files a sweep writes (one CSV row and one
// JSON result per combination and light, one error map per combination), the per-pixel EXR aligned with the PNG,
// and bad input: one error line naming the option, exit code 2, no output written.
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scenes/io/exr_image.h"
#include "shading/techniques/vocabulary.h"
#include "tests/cli/cli_run.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using testsupport::Outcome;
using testsupport::shadowlab;

// A floor and a box on it under the sun, a camera at an angle.
const char* kScene = R"({"objects": [{"primitive": {"type": "plane", "size": [6, 6]}},
  {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}],
  "cameras": [{"position": [3, 5, 6], "target": [0, 0, 0]}],
  "lights": [{"type": "directional", "direction": [-0.5, -1, -0.3]}]})";

class EvalCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = testsupport::temp_dir(std::string("eval_cli_") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::ofstream(dir / "scene.json") << kScene;
  }
  void expect_bad(const std::string& args, const std::string& where, const std::string& out) {
    testsupport::expect_bad_run(dir, args, where, out);
    for (const auto& e : fs::directory_iterator(dir))
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  fs::path dir;
};

size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

TEST_F(EvalCli, SweepWritesCsvJsonAndErrorMaps) {
  const Outcome r = shadowlab(dir, "eval scene.json --techniques shadowmap --filters hard,pcf --biases slope "
                                   "--sizes 128,1024 --size 160x120 --out report");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("Mrays/s"));
  const std::string csv = testsupport::slurp(dir / "report" / "eval.csv");
  EXPECT_EQ(lines(csv), 1u + 4u);  // header, 2 filters x 2 sizes x 1 light
  EXPECT_EQ(csv.rfind("index,combination,technique,filter,bias,map_size,light,", 0), 0u);
  const nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / "report" / "eval.json"));
  ASSERT_EQ(j.at("results").size(), 4u);
  EXPECT_GT(j.at("reference").at("rays").get<size_t>(), 5000u);
  EXPECT_GT(j.at("reference").at("epsilon").get<double>(), 0.0);
  double small = -1, large = -1;
  for (const auto& row : j.at("results")) {
    EXPECT_GT(row.at("scored_pixels").get<size_t>(), 5000u);
    EXPECT_GT(row.at("aliasing_p95").get<double>(), 0.0);  // the classic map has the aliasing measure
    const double e = row.at("false_shadowed_pct").get<double>() + row.at("false_lit_pct").get<double>();
    if (row.at("filter") == "hard" && row.at("map_size") == 128) small = e;
    if (row.at("filter") == "hard" && row.at("map_size") == 1024) large = e;
  }
  EXPECT_GT(small, large);  // a coarser map is further from the exact shadow
  // The page: one table row per result (and the header), one embedded contact sheet per combination.
  const std::string html = testsupport::slurp(dir / "report" / "eval.html");
  size_t rows = 0, images = 0;
  for (size_t at = html.find("<tr>"); at != std::string::npos; at = html.find("<tr>", at + 1)) ++rows;
  for (size_t at = html.find("data:image/png;base64,"); at != std::string::npos;
       at = html.find("data:image/png;base64,", at + 1))
    ++images;
  EXPECT_EQ(rows, 5u);
  EXPECT_EQ(images, 4u);
  for (const char* name : {"shadowmap-hard-slope-128.png", "shadowmap-pcf-slope-128.png", "shadowmap-hard-slope-1024.png",
                           "shadowmap-pcf-slope-1024.png"})
    EXPECT_TRUE(fs::exists(dir / "report" / name)) << name;
}

// Projective shadows (receiver passes) are scored from the factors those passes multiplied in: with the floor
// casting nothing (the article's receivers-only ground), the box's shadow on the floor is nearly exact, while
// `none` misses all of it.
TEST_F(EvalCli, ProjectiveIsScored) {
  std::ofstream(dir / "floor.json") << R"({"objects": [
    {"primitive": {"type": "plane", "size": [6, 6]}, "casts_shadows": false},
    {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}],
    "cameras": [{"position": [3, 5, 6], "target": [0, 0, 0]}],
    "lights": [{"type": "directional", "direction": [-1, -0.8, -0.4]}]})";
  const Outcome r = shadowlab(dir, "eval floor.json --techniques none,projective --filters hard --biases none "
                                   "--sizes 256 --size 160x120 --out report");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / "report" / "eval.json"));
  ASSERT_EQ(j.at("results").size(), 2u);
  double none = -1, projective = -1;
  for (const auto& row : j.at("results")) {
    const double e = row.at("false_shadowed_pct").get<double>() + row.at("false_lit_pct").get<double>();
    (row.at("technique") == "none" ? none : projective) = e;
  }
  EXPECT_GT(none, 1.0);              // the whole shadow is missed
  EXPECT_LT(projective, none / 20);  // the per-caster map finds it
}

// The report's files are written together: when one of them cannot be (here eval.html is taken by a directory),
// none of the others appears and no temporary is left.
TEST_F(EvalCli, ReportFilesAreAllOrNothing) {
  fs::create_directories(dir / "report" / "eval.html");
  const Outcome r = shadowlab(dir, "eval scene.json --techniques shadowmap --filters hard --biases slope --sizes 128 "
                                   "--size 64x48 --out report");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("eval.html"));
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir / "report")) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "eval.html") << e.path();
  }
  EXPECT_EQ(entries, 1u);
}

TEST_F(EvalCli, BadInputWritesNothing) {
  const std::string base = "eval scene.json --size 64x48 --out report ";
  expect_bad(base + "--techniques shadowmap,bogus", "--techniques", "report");
  expect_bad(base + "--sizes 512,abc", "--sizes", "report");
  expect_bad(base + "--sizes 8", "--sizes", "report");
  expect_bad(base + "--sizes 512,", "--sizes", "report");
  expect_bad(base + "--filters soft", "--filters", "report");
  expect_bad(base + "--biases huge", "--biases", "report");
  expect_bad(base + "--techniques cube", "--techniques", "report");  // cube does not serve directional lights
  // Every technique the vocabulary lists but nobody has built yet is refused with the vocabulary's words.
  for (const shading::tech::TechniqueInfo& t : shading::tech::kTechniques) {
    if (t.built) continue;
    const std::string name(t.name);
    expect_bad(base + "--techniques shadowmap," + name, "--techniques", "report");
    EXPECT_THAT(shadowlab(dir, base + "--techniques " + name).err,
                ::testing::HasSubstr("technique " + name + " is not built yet"));
  }
}

// The CSV without its last eight columns: the times (map_pass_ms, camera_pass_ms, score_ms), the shimmer columns
// (empty here) and the aliasing measure (its timing-free values are compared through the JSON in other tests).
std::string without_times(const std::string& csv) {
  std::stringstream in(csv);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    for (int k = 0; k < 8; ++k) line = line.substr(0, line.rfind(','));
    out += line + "\n";
  }
  return out;
}

TEST_F(EvalCli, ShardsMergeIntoTheWholeSweep) {
  const std::string sweep = "eval scene.json --techniques shadowmap --filters hard,pcf --biases slope,constant "
                            "--sizes 128 --size 96x72 ";
  ASSERT_EQ(shadowlab(dir, sweep + "--out whole").code, 0);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(shadowlab(dir, sweep + "--shard " + std::to_string(i) + "/3 --out s" + std::to_string(i)).code, 0);
  // Shard 0 holds combinations 0 and 3, shard 1 combination 1, shard 2 combination 2.
  EXPECT_EQ(lines(testsupport::slurp(dir / "s0" / "eval.csv")), 3u);
  EXPECT_EQ(lines(testsupport::slurp(dir / "s1" / "eval.csv")), 2u);
  const Outcome m = shadowlab(dir, "eval-merge s2 s0 s1 --out merged");
  ASSERT_EQ(m.code, 0) << m.err;
  const std::string whole = testsupport::slurp(dir / "whole" / "eval.csv");
  EXPECT_EQ(lines(whole), 5u);
  EXPECT_EQ(without_times(testsupport::slurp(dir / "merged" / "eval.csv")), without_times(whole));
  for (const auto& e : fs::directory_iterator(dir / "whole"))
    EXPECT_TRUE(fs::exists(dir / "merged" / e.path().filename())) << e.path();
  // A missing shard, a repeated one, another sweep's shard, a bad --shard: one line each, nothing written.
  expect_bad("eval-merge s0 s1 --out m2", "s0/eval.json", "m2");
  expect_bad("eval-merge s0 s1 s1 --out m2", "s1/eval.json", "m2");
  expect_bad("eval-merge s0 s1 whole --out m2", "whole/eval.json", "m2");
  expect_bad("eval-merge s0 s1 nowhere --out m2", "nowhere/eval.json", "m2");
  expect_bad(sweep + "--shard 3/3 --out m2", "--shard", "m2");
  expect_bad(sweep + "--shard 1 --out m2", "--shard", "m2");
  expect_bad(sweep + "--shard -1/2 --out m2", "--shard", "m2");
  // A shard of a sweep as large but over other combinations, or with another cull-front override, is another
  // sweep's.
  ASSERT_EQ(shadowlab(dir, "eval scene.json --techniques shadowmap --filters hard,poisson --biases slope,constant "
                           "--sizes 128 --size 96x72 --shard 2/3 --out other2").code, 0);
  expect_bad("eval-merge s0 s1 other2 --out m2", "other2/eval.json", "m2");
  ASSERT_EQ(shadowlab(dir, sweep + "--cull-front --shard 2/3 --out culled2").code, 0);
  expect_bad("eval-merge s0 s1 culled2 --out m2", "culled2/eval.json", "m2");
  // A damaged report is named with its file and field.
  auto damaged = [&](const std::string& name, const std::function<void(nlohmann::json&)>& change) {
    fs::copy(dir / "s2", dir / name);
    nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / name / "eval.json"));
    change(j);
    std::ofstream(dir / name / "eval.json") << j.dump();
  };
  damaged("bad_shard", [](auto& j) { j["sweep"]["shard"] = "2"; });
  expect_bad("eval-merge s0 s1 bad_shard --out m2", "bad_shard/eval.json: sweep.shard", "m2");
  damaged("no_column", [](auto& j) { j["results"][0].erase("false_lit_pct"); });
  expect_bad("eval-merge s0 s1 no_column --out m2", "no_column/eval.json: results[0]", "m2");
  damaged("foreign_row", [](auto& j) { j["results"][0]["index"] = 1; });  // combination 1 is shard 1's
  expect_bad("eval-merge s0 s1 foreign_row --out m2", "foreign_row/eval.json: results[0].combination", "m2");
}

// A glTF with its own lights (no staged ground): `eval --light 1` with projective scores light 1 alone, named
// (the sweep once read past the chosen light's scene for projective rows).
TEST_F(EvalCli, PickedLightOfAGltfWithProjective) {
  testsupport::GltfFixture f;
  const std::vector<glm::vec3> quad = {{-3, 0, -3}, {3, 0, -3}, {-3, 0, 3}, {3, 0, 3}};
  const std::vector<glm::vec3> box = {{0, 1, 0}, {1, 1, 0}, {0, 1, 1}, {1, 1, 1}};
  f.node({{"mesh", f.mesh(f.positions(quad), f.indices({0, 2, 1, 1, 2, 3}))}});
  f.node({{"mesh", f.mesh(f.positions(box), f.indices({0, 2, 1, 1, 2, 3}))}});
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"name", "sun"}, {"type", "directional"}, {"intensity", 3}},
                                                          {{"name", "lamp"}, {"type", "point"}, {"intensity", 100}}};
  f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"rotation", {-0.7071, 0, 0, 0.7071}}});
  f.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"translation", {0.5, 4, 0.5}}});
  f.write_gltf(dir, "lit");
  const Outcome r = shadowlab(dir, "eval lit.gltf --techniques projective,cube --light 1 --size 64x48 --out lit");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / "lit" / "eval.json"));
  ASSERT_EQ(j.at("results").size(), 2u);
  for (const nlohmann::json& row : j.at("results")) {
    EXPECT_EQ(row.at("light"), 0);
    EXPECT_EQ(row.at("light_name"), "lamp");
  }
}

// Where a label says "scene" (the light's own setting), the row says what the light was rendered with: the
// built-in tutorial's sun is a 2048² d16 map, PCF, slope bias; --sizes and --depth-format replace theirs; esm
// reads no filter (null) and brings its d32f, irregular reads neither bias nor depth format.
TEST_F(EvalCli, RowsSayWhatEachLightWasRenderedWith) {
  const Outcome r = shadowlab(dir, "eval tutorial --techniques shadowmap,esm,irregular --size 64x36 --out used");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("shadowmap-scene-scene-scene (shadowmap pcf slope 2048 d16) light0: "));
  const nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / "used" / "eval.json"));
  ASSERT_EQ(j.at("results").size(), 3u);
  const auto& classic = j.at("results")[0], esm = j.at("results")[1], irregular = j.at("results")[2];
  EXPECT_EQ(classic.at("map_size"), 0);  // the sweep's own column: the scene's
  EXPECT_EQ(classic.at("used_technique"), "shadowmap");
  EXPECT_EQ(classic.at("used_filter"), "pcf");
  EXPECT_EQ(classic.at("used_bias"), "slope");
  EXPECT_EQ(classic.at("used_map_size"), 2048);
  EXPECT_EQ(classic.at("used_depth_format"), "d16");
  EXPECT_TRUE(esm.at("used_filter").is_null());
  EXPECT_EQ(esm.at("used_bias"), "slope");
  EXPECT_EQ(esm.at("used_depth_format"), "d32f");  // the sun's d16 is the classic default: esm brings its own
  EXPECT_TRUE(irregular.at("used_bias").is_null());
  EXPECT_TRUE(irregular.at("used_depth_format").is_null());
  const std::string csv = testsupport::slurp(dir / "used" / "eval.csv");
  EXPECT_NE(csv.find(",light_name,used_technique,used_filter,used_bias,used_map_size,used_depth_format,"), std::string::npos);
  ASSERT_EQ(shadowlab(dir, "eval tutorial --techniques shadowmap --sizes 512 --depth-format d24 --size 64x36 --out used2").code, 0);
  const nlohmann::json k = nlohmann::json::parse(testsupport::slurp(dir / "used2" / "eval.json"));
  EXPECT_EQ(k.at("results")[0].at("used_map_size"), 512);
  EXPECT_EQ(k.at("results")[0].at("used_depth_format"), "d24");
}

// The shadow settings render takes apply to every combination of a sweep whose lights read them: --esm-c changes
// the esm rows and leaves the classic map's rows as they were; a setting no combination reads is refused.
TEST_F(EvalCli, SweepTakesShadowSettings) {
  auto rows = [&](const std::string& extra, const std::string& out) {
    const Outcome r = shadowlab(dir, "eval scene.json --techniques shadowmap,esm --biases constant --sizes 256 "
                                     "--size 160x120 --out " + out + " " + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(testsupport::slurp(dir / out / "eval.json"));
  };
  const nlohmann::json plain = rows("", "plain"), sharp = rows("--esm-c 20", "sharp"),
                       biased = rows("--bias-constant 0.05", "biased");
  ASSERT_EQ(plain.at("results").size(), 2u);
  ASSERT_EQ(sharp.at("results").size(), 2u);
  EXPECT_EQ(plain.at("sweep").at("settings"), nlohmann::json::object());
  EXPECT_EQ(sharp.at("sweep").at("settings"), (nlohmann::json{{"esm-c", 20.0}}));
  EXPECT_EQ(biased.at("sweep").at("settings"), (nlohmann::json{{"bias-constant", 0.05f}}));
  auto errors = [](const nlohmann::json& row) { return row.at("false_lit_pixels").get<size_t>() + row.at("false_shadowed_pixels").get<size_t>(); };
  const auto& classic = plain.at("results")[0], esm = plain.at("results")[1];
  ASSERT_EQ(classic.at("technique"), "shadowmap");
  ASSERT_EQ(esm.at("technique"), "esm");
  EXPECT_NE(sharp.at("results")[1].at("mean_abs_error"), esm.at("mean_abs_error"));
  EXPECT_EQ(errors(sharp.at("results")[0]), errors(classic));
  EXPECT_EQ(sharp.at("results")[0].at("mean_abs_error"), classic.at("mean_abs_error"));
  // A 256² map with the default constant bias has acne on the floor; ten times the bias removes most of it.
  EXPECT_GT(classic.at("false_shadowed_pixels").get<size_t>(), 20u);
  EXPECT_LT(biased.at("results")[0].at("false_shadowed_pixels").get<size_t>() * 4,
            classic.at("false_shadowed_pixels").get<size_t>());

  const std::string base = "eval scene.json --size 64x48 --out report ";
  expect_bad(base + "--techniques shadowmap --esm-c 20", "--esm-c", "report");
  const Outcome none = shadowlab(dir, base + "--techniques shadowmap,lispsm --esm-c 20");
  EXPECT_THAT(none.err, ::testing::HasSubstr("--esm-c: no combination of the sweep reads it")) << none.err;
  expect_bad(base + "--techniques esm --esm-c 200", "--esm-c", "report");
  expect_bad(base + "--techniques cascades --light-angle 2", "--light-angle", "report");  // without pcss
  expect_bad(base + "--poisson-taps 5", "--poisson-taps", "report");
  expect_bad(base + "--depth-format d7", "--depth-format", "report");
  // A shard with other settings belongs to another sweep.
  const std::string sweep = "eval scene.json --techniques shadowmap --biases slope,constant --size 64x48 ";
  ASSERT_EQ(shadowlab(dir, sweep + "--shard 0/2 --out s0").code, 0);
  ASSERT_EQ(shadowlab(dir, sweep + "--bias-constant 0.01 --shard 1/2 --out s1").code, 0);
  expect_bad("eval-merge s0 s1 --out m", "s1/eval.json", "m");
  ASSERT_EQ(shadowlab(dir, sweep + "--shard 1/2 --out s1b").code, 0);
  EXPECT_EQ(shadowlab(dir, "eval-merge s0 s1b --out m").code, 0);
}

// An error in a scene's field is named with the file and the light's own place in it, also with --light.
TEST_F(EvalCli, SceneFieldErrorsNameTheFile) {
  std::ofstream(dir / "two.json") << R"({"objects": [{"primitive": {"type": "plane", "size": [6, 6]}}],
    "lights": [{"type": "directional", "direction": [0, -1, 0]},
               {"type": "directional", "direction": [0, -1, 0], "shadow": {"map_size": 16384}}]})";
  expect_bad("eval two.json --size 32x24 --techniques cascades --light 1 --out r", "two.json: lights[1].shadow.map_size",
             "r");
}

TEST_F(EvalCli, ShimmerColumnsOnRequest) {
  const Outcome r = shadowlab(dir, "eval scene.json --techniques shadowmap --sizes 128,2048 --size 160x120 "
                                   "--shimmer-pixels 0.5 --shimmer-degrees 1 --out report");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(testsupport::slurp(dir / "report" / "eval.json"));
  ASSERT_EQ(j.at("results").size(), 2u);
  for (const auto& row : j.at("results")) {
    EXPECT_TRUE(row.at("shimmer_camera_pct").is_number()) << row;
    EXPECT_TRUE(row.at("shimmer_light_pct").is_number()) << row;
    EXPECT_GE(row.at("shimmer_light_pct").get<double>(), 0.0);
  }
  EXPECT_EQ(j.at("shimmer").at("light_degrees").get<double>(), 1.0);
  expect_bad("eval scene.json --size 32x24 --shimmer-degrees 90 --out r2", "--shimmer-degrees", "r2");
  expect_bad("eval scene.json --size 32x24 --shimmer-pixels nan --out r2", "--shimmer-pixels", "r2");
}

TEST_F(EvalCli, RenderAovAlignsWithThePng) {
  const Outcome r = shadowlab(dir, "render scene.json --size 96x64 --out f.png --aov position,visibility,depth "
                                   "--aov-out f.exr");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir / "f.png"));
  const scenes::io::ExrImage img = scenes::io::read_exr_image(dir / "f.exr");
  EXPECT_EQ(img.width, 96);
  EXPECT_EQ(img.height, 64);
  for (const char* c : {"P.X", "P.Y", "P.Z", "Z", "light0.V", "light0.facing", "A"})
    EXPECT_NE(img.find(c), nullptr) << c;
  EXPECT_EQ(img.find("N.X"), nullptr);
  // Rows are stored in GL order after reading (row 0 the bottom), as in the PNG flipped: the camera looks down
  // at the floor, so the lowest covered pixel of the middle column is nearer (smaller depth) than the highest.
  const auto& z = img.find("Z")->values;
  const auto& a = img.find("A")->values;
  const auto& py = img.find("P.Y")->values;
  int lowest = -1, highest = -1;
  for (int y = 0; y < 64; ++y)
    if (a[size_t(y) * 96 + 48] == 1.0f) {
      if (lowest < 0) lowest = y;
      highest = y;
    }
  ASSERT_GE(lowest, 0);
  ASSERT_GT(highest, lowest + 10);
  EXPECT_LT(z[size_t(lowest) * 96 + 48], z[size_t(highest) * 96 + 48]);
  // The PNG's top row (file row 0) is the EXR's top row too: both show the sky above the floor's far edge.
  EXPECT_LT(highest, 63);
  EXPECT_EQ(a[size_t(63) * 96 + 48], 0.0f);
  EXPECT_EQ(py[size_t(63) * 96 + 48], 0.0f);
  EXPECT_EQ(z[size_t(63) * 96 + 48], 1.0f);  // the sky at the cleared depth, as in a depth buffer
}

TEST_F(EvalCli, RenderAovBadInput) {
  expect_bad("render scene.json --size 32x32 --out f.png --aov position,colour --aov-out f.exr", "--aov", "f.exr");
  expect_bad("render scene.json --size 32x32 --out f.png --aov depth", "--aov", "f.png");
  expect_bad("render scene.json --size 32x32 --out f.png --aov depth --aov-out f.png", "--aov-out", "f.exr");
}

}  // namespace
