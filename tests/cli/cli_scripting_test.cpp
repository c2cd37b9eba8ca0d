// End-to-end tests of the command line as scripts and CI use it (issue 18): every --json document validated
// against its schema in docs/cli/ with valijson (and a broken document refused, so the check can fail); diff's
// metrics, --fail-over and --diff-out; inspect on EXRs written by oiiotool (channels R, Y, depth.Z); the golden
// workflow of `check` failing on a one-pixel change and passing after --update; batches equal to separate runs;
// shards whose merge equals the unsharded run; image sequences; --version; the README's quick start as written.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "scenes/io/exr_image.h"
#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using testsupport::Outcome;
using testsupport::shadowlab;

// The problems valijson finds in `doc` against docs/cli/NAME.schema.json (empty: valid).
std::string schema_problems(const std::string& name, const nlohmann::json& doc) {
  const nlohmann::json schema_doc =
      nlohmann::json::parse(testsupport::slurp(fs::path(SHADOWLAB_SOURCE_DIR) / "docs/cli" / (name + ".schema.json")));
  valijson::Schema schema;
  valijson::SchemaParser parser;
  valijson::adapters::NlohmannJsonAdapter schema_adapter(schema_doc);
  parser.populateSchema(schema_adapter, schema);
  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter target(doc);
  if (validator.validate(schema, target, &results)) return "";
  std::string out;
  valijson::ValidationResults::Error e;
  while (results.popError(e)) {
    std::string path;
    for (const std::string& p : e.context) path += p;
    out += path + ": " + e.description + "\n";
  }
  return out.empty() ? "invalid" : out;
}

// Runs `args` (with --json) and returns its document, checked against the schema `name`.
nlohmann::json json_run(const fs::path& dir, const std::string& args, const std::string& name, int code = 0) {
  const Outcome r = shadowlab(dir, args);
  EXPECT_EQ(r.code, code) << args << "\n" << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out, nullptr, false);
  EXPECT_FALSE(doc.is_discarded()) << args << "\n" << r.out;
  if (doc.is_discarded()) return {};
  EXPECT_EQ(schema_problems(name, doc), "") << args;
  return doc;
}

bool have_oiiotool() { return std::system("command -v oiiotool >/dev/null 2>&1") == 0; }

// Changes one pixel of a PNG (its first channel by 0.5), through OpenImageIO.
void change_one_pixel(const fs::path& png, int x, int y) {
  OIIO::ImageBuf img(png.string());
  ASSERT_TRUE(img.read(0, 0, true, OIIO::TypeDesc::UINT8));
  float v[4] = {};
  img.getpixel(x, y, v, 4);
  v[0] = v[0] > 0.5f ? v[0] - 0.5f : v[0] + 0.5f;
  img.setpixel(x, y, v, 4);
  ASSERT_TRUE(img.write(png.string()));
}

// Runs `eval` on the shared asset `model` with `args` (output in DIR/ev) and expects `rows` results, each under
// `limit` per cent false-lit and false-shadowed.
void expect_eval_close(const fs::path& dir, const std::string& model, const std::string& args, size_t rows,
                       double limit) {
  const Outcome er = shadowlab(dir, "eval '" + (testsupport::assets_dir() / model).string() + "' " + args + " --out ev");
  ASSERT_EQ(er.code, 0) << er.err;
  const nlohmann::json ev = nlohmann::json::parse(testsupport::slurp(dir / "ev" / "eval.json"));
  ASSERT_EQ(ev.at("results").size(), rows);
  for (const nlohmann::json& row : ev.at("results")) {
    EXPECT_LT(row.at("false_lit_pct").get<double>(), limit) << model << " " << row.at("technique");
    EXPECT_LT(row.at("false_shadowed_pct").get<double>(), limit) << model << " " << row.at("technique");
  }
}

class CliScripting : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = testsupport::temp_dir(std::string("cli_scripting_") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  fs::path dir;
};

TEST_F(CliScripting, EveryJsonDocumentMatchesItsSchema) {
  const nlohmann::json list = json_run(dir, "list --json", "list");
  EXPECT_GE(list["techniques"].size(), 8u);
  const nlohmann::json render =
      json_run(dir, "render tutorial --size 64x36 --shadow-size 128 --out f.png --maps maps --aliasing heat.png --json",
               "render");
  ASSERT_EQ(render["jobs"].size(), 1u);
  const nlohmann::json& frame = render["jobs"][0]["frames"][0];
  EXPECT_EQ(frame["pixels"], 64 * 36);
  EXPECT_EQ(frame["maps"][0]["width"], 128);
  EXPECT_EQ(frame["outputs"].size(), 3u);  // the map, the heat map, the frame
  const nlohmann::json inspect = json_run(dir, "inspect maps/light0-sun.exr f.png --json", "inspect");
  ASSERT_EQ(inspect["files"].size(), 2u);
  EXPECT_EQ(inspect["files"][0]["channel"], "Z");
  EXPECT_EQ(inspect["files"][1]["kind"], "frame");
  json_run(dir, "diff f.png f.png --json", "diff");
  ASSERT_EQ(shadowlab(dir, "render tutorial --size 64x36 --shadow-size 128 --depth-format d32f --out g.png --maps maps2")
                .code, 0);
  const nlohmann::json d = json_run(dir, "diff maps/light0-sun.exr maps2/light0-sun.exr --json", "diff", 1);
  EXPECT_TRUE(d["failed"].get<bool>());
  // The validator is no rubber stamp: a document missing a field, or with a wrong type, is refused.
  nlohmann::json broken = d;
  broken.erase("pixels");
  EXPECT_NE(schema_problems("diff", broken), "");
  broken = d;
  broken["over"] = "many";
  EXPECT_NE(schema_problems("diff", broken), "");
  broken = list;
  broken["techniques"][0]["lights"][0] = "laser";
  EXPECT_NE(schema_problems("list", broken), "");
}

TEST_F(CliScripting, DiffReportsMetricsAndHonoursFailOver) {
  ASSERT_EQ(shadowlab(dir, "render tutorial --size 64x36 --out a.png").code, 0);
  fs::copy_file(dir / "a.png", dir / "b.png");
  change_one_pixel(dir / "b.png", 10, 20);
  Outcome r = shadowlab(dir, "diff a.png b.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.out, ::testing::HasSubstr("over tolerance 0: 1 of 2304 pixels"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("largest difference at x 10, y 20"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("PSNR [0-9.]+ dB"));
  EXPECT_EQ(shadowlab(dir, "diff a.png b.png --fail-over 1").code, 0);
  EXPECT_EQ(shadowlab(dir, "diff a.png b.png --fail-over 0.01%").code, 1);  // 1 of 2304 is 0.043 %
  EXPECT_EQ(shadowlab(dir, "diff a.png b.png --fail-over 0.05%").code, 0);
  EXPECT_EQ(shadowlab(dir, "diff a.png b.png --tolerance 0.6").code, 0);
  const nlohmann::json j = json_run(dir, "diff a.png b.png --diff-out heat.png --json", "diff", 1);
  EXPECT_EQ(j["over"], 1);
  EXPECT_NEAR(j["max"].get<double>(), 0.5, 1.0 / 255);
  EXPECT_NEAR(j["rmse"].get<double>(), std::sqrt(0.5 * 0.5 / (2304.0 * 3.0)), 1e-3);
  ASSERT_TRUE(fs::exists(dir / "heat.png"));
  // The heat map is bright exactly at the changed pixel.
  OIIO::ImageBuf heat((dir / "heat.png").string());
  float hot[3], cold[3];
  heat.getpixel(10, 20, hot, 3);
  heat.getpixel(11, 20, cold, 3);
  EXPECT_GT(hot[0] + hot[1] + hot[2], 1.5f);
  EXPECT_LT(cold[0] + cold[1] + cold[2], 0.1f);
  testsupport::expect_bad_run(dir, "diff a.png b.png --fail-over 5x", "--fail-over");
  testsupport::expect_bad_run(dir, "diff a.png b.png --fail-over 101%", "--fail-over");
  // The same picture stored in 16 bits (each byte x as 257 x) is identical to its 8-bit self, not an ulp away
  // from it in most pixels.
  OIIO::ImageBuf wide((dir / "a.png").string());
  ASSERT_TRUE(wide.read(0, 0, true, OIIO::TypeDesc::UINT8));
  wide.set_write_format(OIIO::TypeDesc::UINT16);
  ASSERT_TRUE(wide.write((dir / "a16.png").string()));
  r = shadowlab(dir, "diff a.png a16.png");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_THAT(r.out, ::testing::HasSubstr("over tolerance 0: 0 of 2304 pixels"));
  EXPECT_THAT(shadowlab(dir, "inspect a16.png").out, ::testing::HasSubstr("16 bits per channel"));
}

TEST_F(CliScripting, InspectReadsOtherRenderersExrs) {
  if (!have_oiiotool()) GTEST_SKIP() << "skipped: oiiotool not found (Debian openimageio-tools)";
  auto tool = [&](const std::string& args) {
    return std::system(("cd '" + dir.string() + "' && oiiotool " + args + " >/dev/null 2>&1").c_str());
  };
  ASSERT_EQ(tool("--pattern constant:color=0.25 8x4 1 --chnames R -d float -o r.exr"), 0);
  ASSERT_EQ(tool("--pattern constant:color=12.5 8x4 1 --chnames Y -d half -o y.exr"), 0);
  ASSERT_EQ(tool("--pattern constant:color=0.9,0.8,0.75 8x4 3 --chnames R,G,depth.Z -d float -o layered.exr"), 0);
  Outcome r = shadowlab(dir, "inspect r.exr y.exr layered.exr");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth channel: R (the only channel)"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth channel: Y (the only channel)"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth: min 12.5, max 12.5"));  // not clamped to [0, 1]
  EXPECT_THAT(r.out, ::testing::HasSubstr("coverage: 0.000000 (0 of 32 texels < 1)"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth channel: depth.Z (a depth layer's Z)"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth: min 0.75, max 0.75"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("worldToCamera: unset"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("technique: unset"));
  r = shadowlab(dir, "inspect layered.exr --channel R --png dir_of_previews/x.png");
  EXPECT_EQ(r.code, 2);  // the preview's folder does not exist
  r = shadowlab(dir, "inspect layered.exr r.exr --png previews --range 0,1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "previews" / "layered.png"));
  EXPECT_TRUE(fs::exists(dir / "previews" / "r.png"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("colour map viridis"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("range 0 to 1"));
  testsupport::expect_bad_run(dir, "inspect layered.exr --channel nope", "layered.exr");
  ASSERT_EQ(tool("--pattern constant:color=0.5,0.5 8x4 2 --chnames G,B -d float -o gb.exr"), 0);
  testsupport::expect_bad_run(dir, "inspect gb.exr", "gb.exr");  // no depth channel: --channel is suggested
  EXPECT_THAT(shadowlab(dir, "inspect gb.exr").err, ::testing::HasSubstr("--channel"));
  // Two files with one stem would share one preview: refused before any is written.
  fs::create_directories(dir / "other");
  fs::copy_file(dir / "r.exr", dir / "other" / "r.exr");
  testsupport::expect_bad_run(dir, "inspect r.exr other/r.exr --png same_stems", "other/r.exr", "same_stems");
}

TEST_F(CliScripting, GoldenWorkflowFailsOnOnePixelAndPassesAfterUpdate) {
  std::ofstream(dir / "manifest.json") << R"({"entries": [
    {"name": "room", "scene": "tutorial", "args": ["--size", "64x36", "--shadow-size", "128"], "maps": true},
    {"name": "spot", "scene": "tutorial-spot", "args": ["--size", "48x27"], "tolerance": 0.02}]})";
  Outcome r = shadowlab(dir, "check manifest.json");
  EXPECT_EQ(r.code, 2) << r.err;  // no goldens yet
  EXPECT_THAT(r.err, ::testing::HasSubstr("--update"));
  r = shadowlab(dir, "check manifest.json --update");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "goldens" / "room.png"));
  EXPECT_TRUE(fs::exists(dir / "goldens" / "room-maps" / "light0-sun.exr"));
  const nlohmann::json pass = json_run(dir, "check manifest.json --json", "check");
  EXPECT_EQ(pass["summary"]["passed"], 2);
  change_one_pixel(dir / "goldens" / "room.png", 5, 5);
  r = shadowlab(dir, "check manifest.json");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_THAT(r.out, ::testing::ContainsRegex("room +differs"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("spot +pass"));
  EXPECT_TRUE(fs::exists(dir / "check-diffs" / "room.diff.png"));
  ASSERT_EQ(shadowlab(dir, "check manifest.json --update").code, 0);
  EXPECT_EQ(shadowlab(dir, "check manifest.json").code, 0);
  // A bad manifest is an error naming the field.
  std::ofstream(dir / "bad.json") << R"({"entries": [{"name": "x", "scene": "tutorial", "args": ["--out", "y.png"]}]})";
  testsupport::expect_bad_run(dir, "check bad.json", "bad.json: entries[0].args");
  std::ofstream(dir / "bad2.json") << R"({"entries": [{"name": "../x", "scene": "tutorial"}]})";
  testsupport::expect_bad_run(dir, "check bad2.json", "bad2.json: entries[0].name");
  // An entry whose maps were never updated is an error (exit 2), like a missing frame golden; a folder beside
  // the manifest named like a built-in scene does not hide the scene.
  fs::rename(dir / "goldens" / "room-maps", dir / "room-maps-kept");
  testsupport::expect_bad_run(dir, "check manifest.json", "./goldens/room-maps");
  fs::rename(dir / "room-maps-kept", dir / "goldens" / "room-maps");
  fs::create_directories(dir / "tutorial");
  r = shadowlab(dir, "check manifest.json");
  EXPECT_EQ(r.code, 0) << r.err;
}

// Jobs of a batch file render in one process exactly what separate runs render; its shards, merged, are the
// unsharded run's document.
TEST_F(CliScripting, BatchesAndShards) {
  const std::vector<std::string> lines = {
      "tutorial --size 48x27 --out b_tutorial.png", "duel --size 48x27 --filter pcf --shadow-size 256 --out b_duel.png",
      "tutorial-spot --size 48x27 --shadow-size 128 --out b_spot.png", "# a comment", "",
      "projective --size 48x27 --animate --frames 2 --out b_proj_%d.png"};
  {
    std::ofstream f(dir / "jobs.txt");
    for (const std::string& l : lines) f << l << "\n";
  }
  const nlohmann::json whole = json_run(dir, "render --batch jobs.txt --json", "render");
  ASSERT_EQ(whole["jobs"].size(), 4u);
  EXPECT_EQ(whole["jobs"][1]["where"], "jobs.txt:2");
  EXPECT_EQ(whole["jobs"][3]["frames"][1]["outputs"][0], "b_proj_2.png");
  for (const std::string& l : {lines[0], lines[1], lines[2]}) {
    const std::string separate = std::regex_replace(l, std::regex("--out b_"), "--out s_");
    ASSERT_EQ(shadowlab(dir, "render " + separate).code, 0);
  }
  for (const char* name : {"tutorial", "duel", "spot"})
    EXPECT_EQ(testsupport::slurp(dir / ("b_" + std::string(name) + ".png")),
              testsupport::slurp(dir / ("s_" + std::string(name) + ".png")))
        << name;
  const nlohmann::json s0 = json_run(dir, "render --batch jobs.txt --shard 0/2 --json", "render");
  const nlohmann::json s1 = json_run(dir, "render --batch jobs.txt --shard 1/2 --json", "render");
  EXPECT_EQ(s0["jobs"].size(), 2u);
  std::ofstream(dir / "s0.json") << s0.dump();
  std::ofstream(dir / "s1.json") << s1.dump();
  const nlohmann::json merged = json_run(dir, "render-merge s1.json s0.json", "render");
  // Equal but for the times.
  auto strip = [](nlohmann::json jobs) {
    for (auto& j : jobs)
      for (auto& f : j["frames"])
        for (const char* t : {"total_ms", "shadow_ms", "camera_ms"}) f.erase(t);
    return jobs;
  };
  EXPECT_EQ(strip(merged["jobs"]), strip(whole["jobs"]));
  testsupport::expect_bad_run(dir, "render-merge s0.json", "s0.json");      // a shard is missing
  testsupport::expect_bad_run(dir, "render-merge s0.json s0.json", "s0.json");  // one shard twice
  // A damaged shard document is named with its file and field, whatever is missing or mistyped.
  auto damaged = [&](const char* name, const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json d = s0;
    change(d);
    std::ofstream(dir / name) << d.dump();
  };
  damaged("no_batch.json", [](auto& d) { d.erase("batch"); });
  testsupport::expect_bad_run(dir, "render-merge no_batch.json s1.json", "no_batch.json");
  damaged("bad_count.json", [](auto& d) { d["shard"]["count"] = "2"; });
  testsupport::expect_bad_run(dir, "render-merge bad_count.json s1.json", "bad_count.json: shard.count");
  damaged("no_frames.json", [](auto& d) { d["jobs"][1].erase("frames"); });
  testsupport::expect_bad_run(dir, "render-merge no_frames.json s1.json", "no_frames.json: jobs[1]");
  damaged("foreign_job.json", [](auto& d) { d["jobs"][0]["index"] = 1; });  // shard 0/2 runs jobs 0 and 2
  damaged("other_run.json", [](auto& d) { d["job_scenes"][3] = "duel"; });  // a run whose last job is another scene
  testsupport::expect_bad_run(dir, "render-merge other_run.json s1.json", "s1.json");
  testsupport::expect_bad_run(dir, "render-merge foreign_job.json s1.json", "foreign_job.json: jobs[0].index");
  // Options beside --batch would apply to none of its lines: refused, not ignored.
  testsupport::expect_bad_run(dir, "render --batch jobs.txt --threads 2", "--threads");
  testsupport::expect_bad_run(dir, "render --batch jobs.txt --technique esm --json", "--technique");
  std::ofstream(dir / "badjobs.txt") << "tutorial --out ok.png\nduel --filter soft --out x.png\n";
  testsupport::expect_bad_run(dir, "render --batch badjobs.txt", "badjobs.txt:2", "ok.png");  // nothing rendered
  testsupport::expect_bad_run(dir, "render tutorial duel --out same.png", "--out", "same.png");
}

TEST_F(CliScripting, SequencesVersionNamesAndThreads) {
  Outcome r = shadowlab(dir, "render tutorial --size 32x18 --frames 3 --out 'seq_%02d.png'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"seq_01.png", "seq_02.png", "seq_03.png"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
  testsupport::expect_bad_run(dir, "render tutorial --out 'x_%q.png'", "--out");
  testsupport::expect_bad_run(dir, "render tutorial --out 'x_%d_%d.png'", "--out");
  r = shadowlab(dir, "--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_THAT(r.out, ::testing::MatchesRegex("shadowlab [0-9.]+ \\(revision [0-9a-z-]+, SIMD path [a-z0-9]+\\)\n"));
  // An unnamed light's map is light0.exr, never "light0-.exr".
  std::ofstream(dir / "unnamed.json") << R"({"objects": [{"primitive": {"type": "plane", "size": [4, 4]}}],
    "lights": [{"type": "directional", "direction": [0, -1, 0]}]})";
  ASSERT_EQ(shadowlab(dir, "render unnamed.json --size 16x16 --out u.png --maps umaps").code, 0);
  EXPECT_TRUE(fs::exists(dir / "umaps" / "light0.exr"));
  // More threads than cores: honoured without a word.
  r = shadowlab(dir, "render tutorial --size 32x18 --threads 64 --out t.png");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
}

// From a glTF to a shadow in one line (issue 17): a model with no lights gets a sun, a ground and a camera, said
// on stderr, and the frame shows the model's shadow on the ground (lit-facing pixels the technique shadows).
TEST_F(CliScripting, BareGltfModelGetsASunAGroundAndAShadow) {
  if (!testsupport::have_assets()) GTEST_SKIP() << "skipped: ../shared/assets not found";
  auto shadowed = [&](const std::string& file, const std::string& extra) {
    const Outcome r = shadowlab(dir, "render '" + (testsupport::assets_dir() / file).string() +
                                         "' --size 160x90 --aov visibility --aov-out v.exr --out m.png " + extra);
    EXPECT_EQ(r.code, 0) << file << "\n" << r.err;
    const scenes::io::ExrImage v = scenes::io::read_exr_image(dir / "v.exr");
    const scenes::io::ExrChannel* vis = v.find("light0.V");
    const scenes::io::ExrChannel* facing = v.find("light0.facing");
    size_t n = 0;
    for (size_t i = 0; vis && facing && i < vis->values.size(); ++i) n += facing->values[i] > 0.5f && vis->values[i] < 0.5f;
    return std::make_pair(n, r.err);
  };
  // Every shared asset: none has a light (the ground and sun are added for each), some have a camera.
  size_t models = 0;
  for (const auto& folder : fs::directory_iterator(testsupport::assets_dir())) {
    if (!folder.is_directory()) continue;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      const std::string file = fs::relative(entry.path(), testsupport::assets_dir()).generic_string();
      const auto [n, err] = shadowed(file, "");
      // A shadow a user sees at 160 x 90: 1 % of the frame for the flattest model (vulkan_terrain, 0.29 m tall
      // over 2 m: 144 pixels), far more for the others.
      EXPECT_GT(n, 120u) << file;
      EXPECT_THAT(err, ::testing::HasSubstr("shadowlab: note: ")) << file;
      EXPECT_THAT(err, ::testing::HasSubstr("ground plane")) << file;
      ++models;
    }
  }
  EXPECT_GE(models, 21u);
  // Without the ground the shadow has nothing to fall on.
  EXPECT_LT(shadowed("fox/Fox.gltf", "--no-ground").first, 150u);
  // Other cameras: orbit, by index; bad ones are refused on the option.
  EXPECT_GT(shadowed("fox/Fox.gltf", "--camera orbit:200,30 --sun 90,40").first, 150u);
  testsupport::expect_bad_run(dir, "render " + (testsupport::assets_dir() / "fox/Fox.gltf").string() +
                                       " --camera nowhere --out x.png", "--camera", "x.png");
  testsupport::expect_bad_run(dir, "render tutorial --camera orbit:10 --out x.png", "--camera", "x.png");
  testsupport::expect_bad_run(dir, "render tutorial --sun 10,-5 --out x.png", "--sun", "x.png");
  testsupport::expect_bad_run(dir, "render tutorial --up x --out x.png", "--up", "x.png");
  // Staging options on a scene that is not a bare model would do nothing: refused.
  testsupport::expect_bad_run(dir, "render tutorial --sun 90,40 --out x.png", "--sun", "x.png");
  testsupport::expect_bad_run(dir, "render tutorial --up z --out x.png", "--up", "x.png");
  testsupport::expect_bad_run(dir, "render tutorial --up -y --out x.png", "--up", "x.png");
  const Outcome w = shadowlab(dir, "render tutorial --up w --out x.png");
  EXPECT_EQ(w.err, "shadowlab: error: --up: expected y, z, -y or -z, got 'w'\n");
  // A Y-down model (the Vulkan samples' scene) stands on the ground once turned: its shadow falls there.
  EXPECT_GT(shadowed("vulkan_subpass_scene/subpass_scene_opaque.gltf", "--up=-y").first, 120u);
  testsupport::expect_bad_run(dir, "render tutorial --no-ground --out x.png", "--no-ground", "x.png");
  // The staged sun is a light like any other: --light sun keeps the shadow.
  EXPECT_GT(shadowed("fox/Fox.gltf", "--light sun").first, 150u);
  // The ground is in the map, which the moment maps need (without it their shadows washed out), and only
  // receives under projective, whose casters are not shadowed by their own texture.
  // Each shadows about as many pixels as the classic map (a casting ground blackened the whole fox under
  // projective: its texture falls on every receiver behind it).
  const size_t classic = shadowed("fox/Fox.gltf", "--technique shadowmap").first;
  for (const char* t : {"vsm", "esm", "projective"}) {
    const auto [n, err] = shadowed("fox/Fox.gltf", std::string("--technique ") + t);
    EXPECT_NEAR(double(n), double(classic), 0.2 * double(classic)) << t;
    EXPECT_THAT(err, ::testing::Not(::testing::HasSubstr("warning"))) << t;
  }
  // eval scores each on the scene it renders: the shadow found, against the same reference.
  expect_eval_close(dir, "fox/Fox.gltf", "--techniques shadowmap,esm,projective --size 160x90", 3, 2.0);
}

// The view-following techniques on a staged model, against the exact shadow: a small model under an orbit
// camera (the toy car, 0.2 m, on its cloth), whose ground's corners lie beside the camera. The face-split maps
// took their near distance from those corners, the camera's near plane, and kept almost no texels for the car:
// 3.65 % false-lit at this size as at 640 x 360 (0.20 % now), striped light on its shadowed side.
TEST_F(CliScripting, ViewFollowingMapsOnAStagedModelStayCloseToTheExactShadow) {
  if (!testsupport::have_assets()) GTEST_SKIP() << "skipped: ../shared/assets not found";
  expect_eval_close(dir, "toy_car/ToyCar.gltf", "--techniques cascades,lispsm,frustum-faces --size 320x180", 3, 1.0);
}

// --light NAME|INDEX renders one light alone: the same frame as a scene file holding only that light, by name or
// by index; the maps are that light's alone; unknown lights are refused listing the scene's; a frame error names
// the light's place in the file.
TEST_F(CliScripting, LightPicksOneLightByNameOrIndex) {
  const std::string objects = R"("objects": [{"primitive": {"type": "plane", "size": [8, 8]}},
      {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}],
    "cameras": [{"position": [0, 5, 7], "target": [0, 0, 0]}])";
  const std::string key = R"({"name": "key", "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 2000})";
  const std::string fill = R"({"name": "fill", "type": "spot", "position": [3, 4, 2], "direction": [-0.6, -0.8, -0.4],
      "intensity": 300, "range": 20})";
  std::ofstream(dir / "two.json") << "{" << objects << R"(, "lights": [)" << key << ", " << fill << "]}";
  std::ofstream(dir / "fill.json") << "{" << objects << R"(, "lights": [)" << fill << "]}";
  auto hash = [&](const std::string& args) {
    const nlohmann::json d = json_run(dir, "render " + args + " --size 96x64 --json --out h.png", "render");
    return d.empty() ? std::string() : d["jobs"][0]["frames"][0]["hash"].get<std::string>();
  };
  const std::string alone = hash("fill.json");
  ASSERT_FALSE(alone.empty());
  EXPECT_EQ(hash("two.json --light fill"), alone);
  EXPECT_EQ(hash("two.json --light 1"), alone);
  EXPECT_NE(hash("two.json"), alone);  // both lights: another frame
  EXPECT_NE(hash("two.json --light key"), alone);
  // Only the chosen light's maps are built: the paraboloid lamp of lights.json.
  const std::string lights = (fs::path(SHADOWLAB_SOURCE_DIR) / "docs/examples/lights.json").string();
  const nlohmann::json d = json_run(dir, "render '" + lights + "' --light lamp --size 64x36 --json --out l.png", "render");
  ASSERT_FALSE(d.empty());
  const nlohmann::json& maps = d["jobs"][0]["frames"][0]["maps"];
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_EQ(maps[0]["technique"], "paraboloid");
  EXPECT_EQ(maps[0]["light"], "light0-lamp");
  // Refusals: on the option, listing the lights; a bad setting of the chosen light names it as lights[2].
  const Outcome r = shadowlab(dir, "render two.json --light rim --out x.png");
  EXPECT_THAT(r.err, ::testing::HasSubstr("0 'key', 1 'fill'"));
  testsupport::expect_bad_run(dir, "render two.json --light rim --out x.png", "--light", "x.png");
  testsupport::expect_bad_run(dir, "render two.json --light 2 --out x.png", "--light", "x.png");
  testsupport::expect_bad_run(dir, "eval two.json --light rim --size 16x16 --out ev", "--light", "ev");
  // A value given on the command line is named by its option; one from the file by the light's place there.
  testsupport::expect_bad_run(dir, "render '" + lights + "' --light lamp --split-plane q --out x.png",
                              "--split-plane", "x.png");
  const std::string bulb = R"({"name": "bulb", "type": "point", "position": [0, 3, 0], "intensity": 100,
      "shadow": {"technique": "paraboloid", "params": {"split_plane": "q"}}})";
  std::ofstream(dir / "three.json") << "{" << objects << R"(, "lights": [)" << key << ", " << fill << ", " << bulb << "]}";
  testsupport::expect_bad_run(dir, "render three.json --light bulb --out x.png",
                              "three.json: lights[2].shadow.params.split_plane", "x.png");
}

// The files in `dir` (names only, sorted), for checks that a failed run added none.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (name != "stdout.txt" && name != "stderr.txt") names.push_back(name);  // the harness's own (cli_run.h)
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A run that fails anywhere (its second scene, a later batch line or frame, a check entry, an eval combination)
// leaves none of its files and no folder it made; and what the run-through of 2026-12-04 found unclear is named.
TEST_F(CliScripting, AFailedRunLeavesNothingBehind) {
  const std::string bulb = R"({"objects": [{"primitive": {"type": "box"}}], "lights": [{"type": "point",
      "position": [0, 3, 0], "intensity": 100, "shadow": {"technique": "paraboloid", "params": {"split_plane": "q"}}}]})";
  std::ofstream(dir / "bad_plane.json") << bulb;
  std::ofstream(dir / "jobs_missing.txt") << "tutorial --size 32x18 --out a.png\nnosuch.json --out b.png\n";
  std::ofstream(dir / "jobs_late.txt") << "tutorial --size 32x18 --out a.png\nbad_plane.json --size 32x18 --out b.png\n";
  std::ofstream(dir / "jobs_same.txt") << "tutorial --size 32x18 --out a.png\nduel --size 32x18 --out a.png\n";
  std::ofstream(dir / "jobs_quote.txt") << "tutorial --size 32x18 --out 'a.png\n";
  std::ofstream(dir / "manifest.json") << R"({"goldens": "gold", "entries": [{"name": "a", "scene": "tutorial",
      "args": ["--size", "32x18"]}, {"name": "b", "scene": "bad_plane.json", "args": ["--size", "32x18"]}]})";
  std::ofstream(dir / "manifest_args.json") << R"({"goldens": "gold2", "entries": [{"name": "a", "scene": "tutorial",
      "args": ["--filter", "soft"]}]})";
  fs::create_directory(dir / "f_3.png");  // in the way of a sequence's third frame
  const std::vector<std::string> before = listing(dir);
  testsupport::expect_bad_run(dir, "render tutorial nosuch --size 32x18 --out '{scene}.png'", "nosuch");
  testsupport::expect_bad_run(dir, "render tutorial bad_plane.json --size 32x18 --out '{scene}.png' --maps '{scene}-maps'",
                              "bad_plane.json: lights[0].shadow.params.split_plane");
  testsupport::expect_bad_run(dir, "render --batch jobs_missing.txt", "jobs_missing.txt:2: nosuch.json");
  testsupport::expect_bad_run(dir, "render --batch jobs_late.txt", "jobs_late.txt:2: bad_plane.json");
  testsupport::expect_bad_run(dir, "render --batch jobs_same.txt", "jobs_same.txt:2: --out");
  testsupport::expect_bad_run(dir, "render --batch jobs_quote.txt", "jobs_quote.txt:1");
  testsupport::expect_bad_run(dir, "render tutorial tutorial --size 32x18 --out '{scene}.png'", "--out");
  testsupport::expect_bad_run(dir, "render tutorial --size 32x18 --frames 4 --out 'f_%d.png'", "f_3.png");
  testsupport::expect_bad_run(dir, "render tutorial --size 32x18 --maps no/such/maps --out m.png", "--maps");
  testsupport::expect_bad_run(dir, "check manifest.json --update", "entry b: ./bad_plane.json: lights[0].shadow.params.split_plane");
  testsupport::expect_bad_run(dir, "check manifest_args.json", "entry a: --filter");  // before looking for goldens
  testsupport::expect_bad_run(dir, "eval tutorial --techniques shadowmap,cube --size 32x18 --out ev", "--techniques");
  EXPECT_EQ(listing(dir), before);
  // Options and words that do nothing or are not there.
  testsupport::expect_bad_run(dir, "render tutorial --threads -1 --out t.png", "--threads", "t.png");
  testsupport::expect_bad_run(dir, "render tutorial --filter hard --pcf-taps --out t.png", "--pcf-taps", "t.png");
  testsupport::expect_bad_run(dir, "render duel --technique evsm2 --evsm-negative 3 --out t.png", "--evsm-negative", "t.png");
  testsupport::expect_bad_run(dir, "render tutorial --out ''", "--out");
  testsupport::expect_bad_run(dir, "render tutorial --size --out t.png", "--size", "t.png");  // --out taken as the size
  const Outcome zero = shadowlab(dir, "render tutorial --shadow-size 0 --out t.png");
  EXPECT_THAT(zero.err, ::testing::HasSubstr("16..16384 for every technique but projective")) << zero.err;
  testsupport::expect_bad_run(dir, "frobnicate", "frobnicate");
  testsupport::expect_bad_run(dir, "render tutorial --colour --out t.png", "--colour", "t.png");
  const Outcome sun = shadowlab(dir, "render tutorial --sun 10 --out t.png");
  EXPECT_THAT(sun.err, ::testing::HasSubstr("(AZ,EL)")) << sun.err;
  EXPECT_EQ(listing(dir), before);
  // The same hard-filtered light with and without a light's own pcf_taps under --filter hard: the command line's
  // filter replaces the light's, and the Poisson setting that belonged to it.
  const std::string lights = (fs::path(SHADOWLAB_SOURCE_DIR) / "docs/examples/lights.json").string();
  // A sweep whose second combination is bad fails before the first renders (nothing printed, no folder).
  const Outcome sweep = shadowlab(dir, "eval '" + lights + "' --light ceiling --techniques pyramid --sizes 16,17 "
                                       "--size 32x18 --out ev");
  EXPECT_EQ(sweep.code, 2);
  EXPECT_EQ(sweep.out, "");
  EXPECT_EQ(sweep.err.rfind("shadowlab: error: --sizes: ", 0), 0u) << sweep.err;
  EXPECT_EQ(listing(dir), before);
  ASSERT_EQ(shadowlab(dir, "render '" + lights + "' --light ceiling --filter hard --size 48x27 --out h1.png").code, 0);
  ASSERT_EQ(shadowlab(dir, "render '" + lights + "' --light ceiling --filter pcf --size 48x27 --out p1.png").code, 0);
  EXPECT_NE(testsupport::slurp(dir / "h1.png"), testsupport::slurp(dir / "p1.png"));
  // inspect reports the PNG's own sample size.
  const nlohmann::json info = json_run(dir, "inspect h1.png --json", "inspect");
  ASSERT_FALSE(info.empty());
  EXPECT_EQ(info["files"][0]["bits_per_channel"], 8);
}

// The README's quick start, run as written (the binary path mapped to this build's).
TEST_F(CliScripting, ReadmeQuickStartRunsAsWritten) {
  const std::string readme = testsupport::slurp(fs::path(SHADOWLAB_SOURCE_DIR) / "README.md");
  const size_t at = readme.find("## Quick start");
  ASSERT_NE(at, std::string::npos);
  const size_t open = readme.find("```sh\n", at), close = readme.find("```\n", open + 6);
  ASSERT_NE(open, std::string::npos);
  const std::string block = readme.substr(open + 6, close - open - 6);
  ASSERT_THAT(block, ::testing::HasSubstr("build/cli/shadowlab"));
  fs::create_directories(dir / "build" / "cli");
  fs::create_symlink(SHADOWLAB_CLI, dir / "build" / "cli" / "shadowlab");
  std::ofstream(dir / "quickstart.sh") << "set -e\n" << block;
  const int status = std::system(("cd '" + dir.string() + "' && bash quickstart.sh >out.txt 2>err.txt").c_str());
  EXPECT_EQ(WEXITSTATUS(status), 0) << testsupport::slurp(dir / "err.txt");
  EXPECT_THAT(testsupport::slurp(dir / "out.txt"), ::testing::HasSubstr("exit "));
}

}  // namespace
