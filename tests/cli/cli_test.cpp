// End-to-end tests of the shadowlab executable: each runs the built binary (SHADOWLAB_CLI) on small files in
// a temporary folder of the build tree and checks exit codes, the one-line error shape, that failed runs leave
// no output, and that the files written hold what the scene and matrices say.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scenes/io/exr_map.h"
#include "tests/cli/cli_run.h"
#include "tests/scenes/gltf_fixture.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

using testsupport::Outcome;
using testsupport::shadowlab;
using testsupport::slurp;

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// A 4 × 4 m floor at y = 0 and a unit box standing on it (top at y = 1).
const char* kScene = R"({"objects": [{"primitive": {"type": "plane", "size": [4, 4]}},
  {"primitive": {"type": "box", "size": [1, 1, 1]}, "transform": {"translate": [0, 0.5, 0]}}]})";
// Looking straight down from (0, 5, 0) (eye x = world x, eye y = −world z), orthographic ±2 m, near 1, far 9:
// window depth = (distance − 1) / 8, so the floor is at 0.5 and the box top at 0.375.
const char* kView = "[1,0,0,0, 0,0,1,0, 0,-1,0,0, 0,0,-5,1]";
const char* kProj = "[0.5,0,0,0, 0,0.5,0,0, 0,0,-0.25,0, 0,0,-1.25,1]";

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = testsupport::temp_dir(std::string("cli_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    write(dir / "scene.json", kScene);
    write(dir / "m.json", std::string(R"({"view": )") + kView + R"(, "proj": )" + kProj + "}");
  }
  // A bad-input run: exit code 2, exactly one line `shadowlab: error: WHERE: what`, and no file named `out`.
  void expect_bad(const std::string& args, const std::string& where, const std::string& out = "") {
    testsupport::expect_bad_run(dir, args, where, out);
    for (const auto& e : fs::directory_iterator(dir))  // no temporary left behind either
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  std::string shadowmap(const std::string& extra) {
    return "shadowmap --scene scene.json --light-matrix m.json --size 16x16 --format d32f --out d.exr " + extra;
  }
  fs::path dir;
};

TEST_F(Cli, ShadowmapMatchesAnalyticDepth) {
  const Outcome r = shadowlab(dir, shadowmap(""));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const scenes::io::ExrMap map = scenes::io::read_exr_map(dir / "d.exr");
  ASSERT_EQ(map.width, 16);
  ASSERT_EQ(map.height, 16);
  EXPECT_EQ(map.technique, "shadowmap");
  EXPECT_EQ(map.encoding, "window-depth");
  EXPECT_EQ(map.depth_format, "d32f");
  // The box spans NDC x, y in [−0.25, 0.25]: texels 6..9. Everything else is floor.
  EXPECT_NEAR(map.at(8, 8), 0.375f, 1e-6f);
  EXPECT_NEAR(map.at(6, 9), 0.375f, 1e-6f);
  EXPECT_NEAR(map.at(0, 0), 0.5f, 1e-6f);
  EXPECT_NEAR(map.at(15, 3), 0.5f, 1e-6f);
  EXPECT_NEAR(map.at(5, 8), 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(map.world_to_ndc[3][2], -0.25f * -5.0f - 1.25f);  // proj · view, translation z
  EXPECT_FLOAT_EQ(map.world_to_camera[3][2], -5.0f);
}

TEST_F(Cli, ShadowmapD16AndViewProjAndGltf) {
  // view_proj alone, d16 codes, and a glTF file: clip z = y / 4, so the triangle at y = 1 has window depth
  // 0.625; in NDC it is (−1, 1), (0, 1), (0, −1): the upper-left part of the map.
  testsupport::GltfFixture f;
  f.node({{"mesh", f.mesh(f.positions({{-2, 1, 2}, {0, 1, 2}, {0, 1, -2}}))}});
  f.write_glb(dir, "tri");
  write(dir / "vp.json", R"({"view_proj": [0.5,0,0,0, 0,0,0.25,0, 0,0.5,0,0, 0,0,0,1]})");
  const Outcome r = shadowlab(dir, "shadowmap --scene tri.glb --light-matrix vp.json --size 8x8 --format d16 --out t.exr");
  ASSERT_EQ(r.code, 0) << r.err;
  const scenes::io::ExrMap map = scenes::io::read_exr_map(dir / "t.exr");
  EXPECT_EQ(map.depth_format, "d16");
  EXPECT_FLOAT_EQ(map.at(3, 7), float(std::lround(0.625 * 65535)) / 65535.0f);  // under the triangle
  EXPECT_EQ(map.at(3, 0), 1.0f);                                                  // outside: cleared
  EXPECT_EQ(map.at(7, 7), 1.0f);
}

TEST_F(Cli, ShadowmapRepeatPrintsTimes) {
  const Outcome r = shadowlab(dir, shadowmap("--repeat 3 --threads 0 --cull back --offset 1.1,4"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::ContainsRegex("^median [0-9.]+ ms, min [0-9.]+ ms"));
  EXPECT_TRUE(fs::exists(dir / "d.exr"));
}

TEST_F(Cli, InspectPrintsHeaderAndPreview) {
  ASSERT_EQ(shadowlab(dir, shadowmap("")).code, 0);
  const Outcome r = shadowlab(dir, "inspect d.exr --png preview.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("size: 16x16"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("technique: shadowmap"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("coverage: 1.000000"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("depth: min 0.375, max 0.5"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("worldToCamera: [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, -5, 1]"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("worldToNDC: ["));
  EXPECT_TRUE(fs::exists(dir / "preview.png"));
}

TEST_F(Cli, DiffExitCodes) {
  ASSERT_EQ(shadowlab(dir, shadowmap("")).code, 0);
  fs::copy_file(dir / "d.exr", dir / "same.exr");
  ASSERT_EQ(shadowlab(dir, shadowmap("--offset 0,100000")).code, 0);  // d.exr now pushed back
  fs::rename(dir / "d.exr", dir / "other.exr");
  Outcome r = shadowlab(dir, "diff same.exr same.exr");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("max 0, mean 0"));
  r = shadowlab(dir, "diff same.exr other.exr");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("over tolerance 0: 256 of 256 pixels"));
  EXPECT_EQ(shadowlab(dir, "diff same.exr other.exr --tolerance 0.5").code, 0);
  ASSERT_EQ(shadowlab(dir, "shadowmap --scene scene.json --light-matrix m.json --size 8x8 --format d32f --out s.exr")
                .code, 0);
  expect_bad("diff same.exr s.exr", "s.exr");  // sizes differ
}

TEST_F(Cli, ListNamesScenesAndTables) {
  const Outcome r = shadowlab(dir, "list");
  ASSERT_EQ(r.code, 0);
  EXPECT_THAT(r.out, ::testing::ContainsRegex("scene +tutorial +[^\n]+"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("technique +shadowmap"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("[lights: directional, spot; map 1024² d16]"));  // shadowmap's defaults
  EXPECT_THAT(r.out, ::testing::HasSubstr("[lights: directional, spot, point; grid of at most 4096² cells]"));  // irregular's
  EXPECT_THAT(r.out, ::testing::ContainsRegex("technique +none +[^\n]+\\[lights: [a-z, ]+\\]"));  // no map
  EXPECT_THAT(r.out, ::testing::ContainsRegex("filter +pcf"));
  EXPECT_EQ(shadowlab(dir, "--help").code, 0);
  EXPECT_EQ(shadowlab(dir, "shadowmap --help").code, 0);
}

// A built-in scene's name is the scene even where the working folder holds a folder of that name (as `eval
// tutorial --out tutorial` leaves one); a file of that name is read as the file; any other folder is refused.
TEST_F(Cli, BuiltinSceneNamesAreNotHiddenByFolders) {
  fs::create_directory(dir / "tutorial");
  const Outcome r = shadowlab(dir, "render tutorial --size 32x18 --out t.png");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "t.png"));
  write(dir / "duel", R"({"objects": [)");
  expect_bad("render duel --out d.png", "duel", "d.png");
  fs::create_directory(dir / "nowhere");
  expect_bad("render nowhere --out n.png", "nowhere", "n.png");
}

TEST_F(Cli, RenderTutorialWritesFrameAndMaps) {
  const Outcome r = shadowlab(dir, "render tutorial --size 48x32 --shadow-size 64 --threads 2 --out f.png --maps maps --stats");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::ContainsRegex("frame 1: total [0-9.]+ ms"));
  EXPECT_TRUE(fs::exists(dir / "f.png"));
  size_t maps = 0;
  for (const auto& e : fs::directory_iterator(dir / "maps")) maps += e.path().extension() == ".exr";
  EXPECT_GE(maps, 1u);
  EXPECT_EQ(shadowlab(dir, "diff f.png f.png").code, 0);
}

// The tutorial's knobs reach the frame: front faces in the map with no bias show acne, back faces do not.
TEST_F(Cli, RenderCullFrontAndPoissonTapsChangeTheFrame) {
  const std::string base = "render tutorial --size 96x54 --shadow-size 256 --bias none --filter poisson --poisson-taps 16";
  ASSERT_EQ(shadowlab(dir, base + " --cull-front --out back.png").code, 0);
  ASSERT_EQ(shadowlab(dir, base + " --no-cull-front --out front.png").code, 0);
  EXPECT_EQ(shadowlab(dir, "diff back.png front.png --tolerance 0.05").code, 1);
}

// The bias values and the Poisson spread are settable: a larger constant bias removes acne, a wider disc
// softens the penumbra.
TEST_F(Cli, RenderBiasValuesAndSpreadChangeTheFrame) {
  const std::string base = "render tutorial --size 96x54 --shadow-size 256 --threads 2";
  ASSERT_EQ(shadowlab(dir, base + " --bias constant --bias-constant 0 --filter hard --out c0.png").code, 0);
  ASSERT_EQ(shadowlab(dir, base + " --bias constant --bias-constant 0.01 --filter hard --out c1.png").code, 0);
  EXPECT_EQ(shadowlab(dir, "diff c0.png c1.png --tolerance 0.05").code, 1);
  ASSERT_EQ(shadowlab(dir, base + " --filter poisson --out s0.png").code, 0);
  ASSERT_EQ(shadowlab(dir, base + " --filter poisson --poisson-spread 0.01 --out s1.png").code, 0);
  EXPECT_EQ(shadowlab(dir, "diff s0.png s1.png").code, 1);
}

TEST_F(Cli, BadInputIsOneLineAndExitTwo) {
  expect_bad(shadowmap("").replace(shadowmap("").find("scene.json"), 10, "missing.json"), "missing.json", "d.exr");
  write(dir / "trunc.json", R"({"objects": [)");
  expect_bad(shadowmap("").replace(shadowmap("").find("scene.json"), 10, "trunc.json"), "trunc.json", "d.exr");
  write(dir / "lying.glb", std::string("glTF\x02\0\0\0\xff\xff\0\0", 12));
  expect_bad("render lying.glb --out f.png", "lying.glb", "f.png");
  expect_bad("render teapot --out f.png", "teapot", "f.png");
  expect_bad("render tutorial --technique raytraced --out f.png", "--technique", "f.png");
  expect_bad("render tutorial --filter vsm --out f.png", "--filter", "f.png");
  expect_bad("render tutorial --size 0x10 --out f.png", "--size", "f.png");
  expect_bad("render tutorial --size 16385x10 --out f.png", "--size", "f.png");
  expect_bad("render tutorial --shadow-size 0 --out f.png", "--shadow-size", "f.png");
  expect_bad("render tutorial --poisson-taps 5 --out f.png", "--poisson-taps", "f.png");
  expect_bad("render tutorial --poisson-taps 0 --out f.png", "--poisson-taps", "f.png");  // not "the light's own"
  expect_bad("render tutorial --poisson-spread -1 --out f.png", "--poisson-spread", "f.png");
  expect_bad("render tutorial --filter poisson --poisson-spread 2 --out f.png", "--poisson-spread", "f.png");
  {  // a side beyond long long is quoted as given, not as CLI11's saturated 9223372036854775807
    const auto r = shadowlab(dir, "render tutorial --shadow-size 99999999999999999999 --out f.png");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "shadowlab: error: --shadow-size: 99999999999999999999 is outside 1..16384 (16..16384 for "
                     "every technique but projective)\n");
  }
  expect_bad("render tutorial --bias-constant nan --out f.png", "--bias-constant", "f.png");
  expect_bad("render tutorial --stratify diagonal --out f.png", "--stratify", "f.png");
  expect_bad("render tutorial --filter hard --poisson-variant tutorial --out f.png", "--poisson-variant", "f.png");
  expect_bad("render tutorial --fit auto --fit-cutoff 10 --out f.png", "--fit-cutoff", "f.png");
  expect_bad("render tutorial --fit loose --out f.png", "--fit", "f.png");
  expect_bad(shadowmap("--format d8"), "--format", "d.exr");
  expect_bad(shadowmap("--cull sideways"), "--cull", "d.exr");
  write(dir / "nan.json", R"({"objects": [{"mesh": {"positions": [0, 0, 0, 1, 0, 0, 0, 1e39, 0], "indices": [0, 1, 2]}}]})");
  expect_bad(shadowmap("").replace(shadowmap("").find("scene.json"), 10, "nan.json"), "nan.json", "d.exr");
  write(dir / "empty.json", R"({"objects": [{"mesh": {"positions": [], "indices": []}}]})");
  expect_bad(shadowmap("").replace(shadowmap("").find("scene.json"), 10, "empty.json"), "empty.json", "d.exr");
  write(dir / "short.json", R"({"view_proj": [1, 0, 0]})");
  expect_bad(shadowmap("").replace(shadowmap("").find("m.json"), 6, "short.json"), "short.json", "d.exr");
  // Issue 23: a number too large for a double ended in "internal error: [json.exception.out_of_range.406]".
  write(dir / "huge.json", R"({"view_proj": [1e999, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]})");
  expect_bad(shadowmap("").replace(shadowmap("").find("m.json"), 6, "huge.json"), "huge.json", "d.exr");
  // Issue 23: a run that fails on its last output left the maps it had written; now it leaves nothing new
  // (the PNG's place is taken by a directory, so only its rename fails).
  fs::create_directory(dir / "taken.png");
  expect_bad("render tutorial --size 32x32 --out taken.png --maps newmaps", "taken.png");
  EXPECT_FALSE(fs::exists(dir / "newmaps"));
  fs::remove(dir / "taken.png");
  // Issue 23: a truncated PNG made libpng print a second line before ours.
  {
    ASSERT_EQ(shadowlab(dir, "render tutorial --size 64x36 --out whole.png").code, 0);
    const std::string png = testsupport::slurp(dir / "whole.png");
    std::ofstream(dir / "cut.png", std::ios::binary) << png.substr(0, png.size() / 2);
    expect_bad("diff whole.png cut.png", "cut.png");
    // A file that is not what its extension says is refused by that format's reader, not read by whichever
    // other reader accepts it (OpenImageIO would otherwise try all of them, LibRaw included).
    fs::copy_file(dir / "whole.png", dir / "frame.exr");
    expect_bad("inspect frame.exr", "frame.exr");
    write(dir / "words.png", "not an image at all, only words");
    expect_bad("diff whole.png words.png", "words.png");
    ASSERT_EQ(shadowlab(dir, "render tutorial --size 16x16 --maps m --out small.png").code, 0);
    fs::copy_file(dir / "m" / "light0-sun.exr", dir / "map.png");
    expect_bad("diff map.png map.png", "map.png");
    // A folder named with a trailing separator is that folder: its parent (here ".") is the one that must exist.
    ASSERT_EQ(shadowlab(dir, "render tutorial --size 16x16 --maps slash/ --out slash.png").code, 0);
    EXPECT_TRUE(fs::is_regular_file(dir / "slash" / "light0-sun.exr"));
    const Outcome nested = shadowlab(dir, "render tutorial --size 16x16 --maps no/such/ --out slash2.png");
    EXPECT_EQ(nested.err, "shadowlab: error: --maps: directory no does not exist\n");
  }
  // Issue 23: a valid map wider than a frame target; its preview is refused in our words, not the target's.
  {
    scenes::io::ExrMap wide;
    wide.width = 16385;
    wide.height = 1;
    wide.z.assign(16385, 0.5f);
    wide.depth_format = "d32f";
    scenes::io::write_exr_map(dir / "wide.exr", wide);
    expect_bad("inspect wide.exr --png wide.png", "--png", "wide.png");
    EXPECT_EQ(shadowlab(dir, "inspect wide.exr").code, 0);
  }
  // Issue 23: absurd thread counts are refused on the option (10^8 ended in "out of memory").
  expect_bad("render tutorial --size 16x16 --threads 100000000 --out t.png", "--threads", "t.png");
  expect_bad(shadowmap("--threads -2"), "--threads", "d.exr");
  expect_bad("inspect nothing.exr", "nothing.exr");
  expect_bad("render tutorial --size 16x16 --out nodir/f.png", "--out");
  expect_bad("diff nothing.exr d.exr", "nothing.exr");
  expect_bad("shadowmap --scene scene.json --light-matrix m.json --size 4x --format d16 --out d.exr", "--size", "d.exr");
}

}  // namespace

TEST(CliAliasing, RenderMeasuresAliasingAndWritesItsHeatMap) {
  const fs::path dir = testsupport::temp_dir("cli_aliasing");
  const Outcome r = shadowlab(dir, "render duel --technique cascades --size 96x54 --threads 2 --out f.png --aliasing heat.png");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::ContainsRegex("aliasing light0-sun \\(cascades\\): max [0-9.e+]+, p95 [0-9.e+]+, mean "
                                              "[0-9.e+]+ pixels per texel over [0-9]+ lit-facing pixels; storage "
                                              "factor [0-9.e+]+"));
  EXPECT_TRUE(fs::exists(dir / "heat.png"));
  EXPECT_TRUE(fs::exists(dir / "f.png"));
  // Nothing to measure: refused, and neither file written.
  testsupport::expect_bad_run(dir, "render duel --technique none --size 32x32 --out g.png --aliasing h.png",
                              "--aliasing", "g.png");
  EXPECT_FALSE(fs::exists(dir / "h.png"));
  testsupport::expect_bad_run(dir, "render duel --size 32x32 --out g.png --aliasing h.jpg", "--aliasing", "g.png");
}

namespace {

// Issue 23: an EXR whose header declares a 2 GiB string attribute made `inspect` (and `diff`, through
// OpenImageIO) allocate 2.2 GB and spend over a minute before failing; both answer from the size field.
TEST_F(Cli, ExrAttributeClaimingGigabytesFailsFast) {
  ASSERT_EQ(shadowlab(dir, shadowmap("")).code, 0);
  std::string bytes = slurp(dir / "d.exr");
  std::string attribute("note\0string\0\xff\xff\xff\x7f", 16);  // size 2^31 - 1, little-endian
  write(dir / "huge.exr", bytes.substr(0, 8) + attribute + "abcd" + bytes.substr(8));
  expect_bad("inspect huge.exr", "huge.exr");
  expect_bad("diff huge.exr d.exr", "huge.exr");
  expect_bad("inspect huge.exr --png p.png", "huge.exr", "p.png");
}

}  // namespace
