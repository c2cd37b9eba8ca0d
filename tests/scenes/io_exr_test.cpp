// EXR shadow maps: written then read back by shadowlab, by OpenEXR directly (row order on disk), and by the
// command-line tools exrheader and oiiotool (which must show the Z channel and the matrices); errors name the
// file and leave nothing behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfBoxAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/io_error.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using scenes::io::ExrMap;
using scenes::io::IoError;

// A 3 × 2 d16 map whose texels are all different: bottom row codes 0, 13107, 26214; top row 39321, 52428, 65535
// (0, 0.2, 0.4 / 0.6, 0.8, 1 exactly), with distinctive matrices and two passes.
ExrMap sample_map(raster::DepthTarget& target) {
  const uint16_t codes[2][3] = {{0, 13107, 26214}, {39321, 52428, 65535}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) target.row<uint16_t>(y)[x] = codes[y][x];
  ExrMap m = scenes::io::exr_map_from(target);
  m.world_to_camera = glm::lookAt(glm::vec3(1.5f, 8.25f, -3.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  m.world_to_ndc = glm::perspective(0.75f, 1.5f, 0.5f, 40.0f) * m.world_to_camera;
  m.world_to_camera[3][0] = 123.5f;  // a value easy to find in the tools' output
  m.technique = "cube-test";
  m.encoding = "window-depth";
  scenes::io::MapPass p0, p1;
  p0.label = "+X";
  p0.viewport = raster::Rect{0, 0, 1, 2};
  p0.world_to_camera = glm::mat4(2.0f);
  p0.world_to_ndc = glm::mat4(3.0f);
  p1.label = "-X";
  p1.viewport = raster::Rect{1, 0, 2, 1};
  p1.world_to_camera = glm::translate(glm::mat4(1.0f), glm::vec3(7.0f, 8.0f, 9.0f));
  p1.world_to_ndc = glm::mat4(0.5f);
  m.passes = {p0, p1};
  return m;
}

TEST(IoExr, RoundTripThroughShadowlab) {
  const fs::path dir = testsupport::temp_dir("io_exr_roundtrip");
  raster::DepthTarget target(3, 2, raster::DepthFormat::d16);
  const ExrMap m = sample_map(target);
  EXPECT_EQ(m.depth_format, "d16");
  EXPECT_EQ(m.at(1, 0), 0.2f);  // code / 65535
  const fs::path file = dir / "map.exr";
  scenes::io::write_exr_map(file, m);
  const ExrMap r = scenes::io::read_exr_map(file);
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_EQ(r.at(x, y), target.value(x, y)) << x << ", " << y;
  EXPECT_EQ(r.world_to_camera, m.world_to_camera);
  EXPECT_EQ(r.world_to_ndc, m.world_to_ndc);
  EXPECT_EQ(r.technique, "cube-test");
  EXPECT_EQ(r.depth_format, "d16");
  EXPECT_EQ(r.encoding, "window-depth");
  ASSERT_EQ(r.passes.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(r.passes[i].label, m.passes[i].label);
    EXPECT_EQ(r.passes[i].viewport, m.passes[i].viewport);
    EXPECT_EQ(r.passes[i].world_to_camera, m.passes[i].world_to_camera);
    EXPECT_EQ(r.passes[i].world_to_ndc, m.passes[i].world_to_ndc);
  }
  // Only the map itself is left in the directory (no temporary file).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(IoExr, RowsAreTopFirstOnDiskAndMatricesInValuePtrOrder) {
  const fs::path dir = testsupport::temp_dir("io_exr_rows");
  raster::DepthTarget target(3, 2, raster::DepthFormat::d16);
  const ExrMap m = sample_map(target);
  const fs::path file = dir / "map.exr";
  scenes::io::write_exr_map(file, m);
  // Read with OpenEXR itself: EXR's y grows downward, so file row 0 must be the GL top row (y = 1).
  Imf::InputFile in(file.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  ASSERT_EQ(dw.min.x, 0);
  ASSERT_EQ(dw.min.y, 0);
  ASSERT_EQ(in.header().channels().findChannel("Z")->type, Imf::FLOAT);
  std::vector<float> px(6);
  Imf::FrameBuffer fb;
  fb.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(px.data()), sizeof(float), 3 * sizeof(float)));
  in.setFrameBuffer(fb);
  in.readPixels(0, 1);
  const float expected[6] = {0.6f, 0.8f, 1.0f, 0.0f, 0.2f, 0.4f};  // top row first
  for (int k = 0; k < 6; ++k) EXPECT_EQ(px[size_t(k)], expected[k]) << k;
  // M44f memory order equals glm::value_ptr order: x[3][0] is the translation x of a view matrix.
  const auto* wc = in.header().findTypedAttribute<Imf::M44fAttribute>("worldToCamera");
  ASSERT_NE(wc, nullptr);
  EXPECT_EQ(wc->value().x[3][0], 123.5f);
  EXPECT_EQ(wc->value().x[1][2], m.world_to_camera[1][2]);
}

// Runs a command and returns its standard output (empty when it cannot run).
std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  pclose(p);
  return out;
}

bool have_tool(const char* name) {
  return std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0;
}

TEST(IoExr, ExrheaderShowsZChannelAndMatrices) {
  if (!have_tool("exrheader")) GTEST_SKIP() << "skipped: exrheader not found (Debian package openexr)";
  const fs::path dir = testsupport::temp_dir("io_exr_exrheader");
  raster::DepthTarget target(3, 2, raster::DepthFormat::d16);
  const fs::path file = dir / "map.exr";
  scenes::io::write_exr_map(file, sample_map(target));
  const std::string out = run("exrheader '" + file.string() + "'");
  EXPECT_NE(out.find("Z, 32-bit floating-point"), std::string::npos) << out;
  EXPECT_NE(out.find("worldToCamera (type m44f)"), std::string::npos) << out;
  EXPECT_NE(out.find("worldToNDC (type m44f)"), std::string::npos) << out;
  EXPECT_NE(out.find("123.5"), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:depthFormat (type string): \"d16\""), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:technique (type string): \"cube-test\""), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:pass1:viewport (type box2i)"), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:pass1:worldToNDC (type m44f)"), std::string::npos) << out;
  // M44f rows are glm columns: the translation (7, 8, 9) of pass 1's view is the last printed row.
  EXPECT_NE(out.find("    7 8 9 1)"), std::string::npos) << out;
}

TEST(IoExr, OiiotoolShowsZChannelAndMatrices) {
  if (!have_tool("oiiotool")) GTEST_SKIP() << "skipped: oiiotool not found (Debian package openimageio-tools)";
  const fs::path dir = testsupport::temp_dir("io_exr_oiiotool");
  raster::DepthTarget target(3, 2, raster::DepthFormat::d16);
  const fs::path file = dir / "map.exr";
  scenes::io::write_exr_map(file, sample_map(target));
  const std::string out = run("oiiotool --info -v '" + file.string() + "' 2>&1");
  EXPECT_NE(out.find("1 channel, float openexr"), std::string::npos) << out;
  EXPECT_NE(out.find("channel list: Z\n"), std::string::npos) << out;
  // Matrices print as their 16 floats in memory order: the translation x (123.5) is the 13th.
  const size_t wc = out.find("worldToCamera: ");
  ASSERT_NE(wc, std::string::npos) << out;
  EXPECT_NE(out.find(", 123.5, ", wc), std::string::npos) << out;
  EXPECT_NE(out.find("worldToNDC: "), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:depthFormat: \"d16\""), std::string::npos) << out;
  EXPECT_NE(out.find("shadowlab:pass1:worldToCamera: 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1"),
            std::string::npos)
      << out;
}

TEST(IoExr, ErrorsNameTheFileAndLeaveNothingBehind) {
  const fs::path dir = testsupport::temp_dir("io_exr_errors");
  try {
    scenes::io::read_exr_map(dir / "missing.exr");
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "missing.exr").string() + ": no such file");
  }
  raster::DepthTarget target(3, 2, raster::DepthFormat::d32f);
  ExrMap bad = scenes::io::exr_map_from(target);
  bad.z.pop_back();
  EXPECT_THROW(scenes::io::write_exr_map(dir / "bad.exr", bad), IoError);
  ExrMap bad_format = scenes::io::exr_map_from(target);
  bad_format.depth_format = "d15";
  try {
    scenes::io::write_exr_map(dir / "bad.exr", bad_format);
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "bad.exr").string() + ": depth format 'd15' is not d16, d24 or d32f");
  }
  try {
    scenes::io::write_exr_map(dir / "no" / "such" / "dir.exr", scenes::io::exr_map_from(target));
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_EQ(e.file(), dir / "no" / "such" / "dir.exr");
  }
  // A file that is not an EXR.
  {
    std::FILE* f = std::fopen((dir / "junk.exr").c_str(), "w");
    std::fputs("not an exr", f);
    std::fclose(f);
  }
  EXPECT_THROW(scenes::io::read_exr_map(dir / "junk.exr"), IoError);
  // Nothing but the junk file was created.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(IoExr, AFailedWriteKeepsThePreviousFile) {
  const fs::path dir = testsupport::temp_dir("io_exr_keep");
  raster::DepthTarget target(3, 2, raster::DepthFormat::d32f);
  target.clear(0.25f);
  ExrMap good = scenes::io::exr_map_from(target);
  good.depth_format = "d32f";
  scenes::io::write_exr_map(dir / "map.exr", good);
  ExrMap bad = good;
  bad.passes.push_back({"oops", raster::Rect{2, 0, 5, 1}, glm::mat4(1.0f), glm::mat4(1.0f)});
  EXPECT_THROW(scenes::io::write_exr_map(dir / "map.exr", bad), IoError);
  EXPECT_EQ(scenes::io::read_exr_map(dir / "map.exr").at(0, 0), 0.25f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace

// Issue 23: an EXR from elsewhere whose pass viewport starts at -2^31 was accepted after a signed overflow; a
// viewport outside the map is now refused, naming the attribute.
TEST(IoExr, PassViewportsOutsideTheMapAreRefused) {
  const fs::path dir = testsupport::temp_dir("io_exr_viewport");
  const fs::path file = dir / "bad.exr";
  Imf::Header header(4, 4);
  header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
  header.insert("shadowlab:passCount", Imf::IntAttribute(1));
  header.insert("shadowlab:pass0:viewport",
                Imf::Box2iAttribute(Imath::Box2i(Imath::V2i(std::numeric_limits<int>::min(), 0), Imath::V2i(3, 3))));
  header.insert("shadowlab:pass0:worldToCamera", Imf::M44fAttribute(Imath::M44f()));
  header.insert("shadowlab:pass0:worldToNDC", Imf::M44fAttribute(Imath::M44f()));
  std::vector<float> z(16, 0.5f);
  {
    Imf::OutputFile out(file.c_str(), header);
    Imf::FrameBuffer fb;
    fb.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float), 4 * sizeof(float)));
    out.setFrameBuffer(fb);
    out.writePixels(4);
  }
  try {
    scenes::io::read_exr_map(file);
    FAIL() << "no exception";
  } catch (const scenes::io::IoError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": shadowlab:pass0:viewport lies outside the 4 x 4 map");
  }
}

namespace exr_header_tests {

// A valid 4 × 4 Z map on disk, as bytes, for tests that then damage its header.
std::string small_map_bytes(const fs::path& dir) {
  raster::DepthTarget target(4, 4, raster::DepthFormat::d32f);
  ExrMap m = scenes::io::exr_map_from(target);
  scenes::io::write_exr_map(dir / "small.exr", m);
  std::ifstream in(dir / "small.exr", std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void put(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// Issue 23: a string attribute whose size field says 2^31 − 1 bytes made OpenEXR grow a string to 2 GB (over a
// minute) before failing at the end of the file; it is refused from the size field alone, in milliseconds.
TEST(IoExr, AnAttributeLargerThanTheFileIsRefusedBeforeReading) {
  const fs::path dir = testsupport::temp_dir("io_exr_huge_attribute");
  const std::string bytes = small_map_bytes(dir);
  std::string attribute = std::string("note\0string\0", 12);
  const uint32_t size = 0x7fffffff;
  attribute.append(reinterpret_cast<const char*>(&size), 4);  // little-endian, as EXR stores it
  attribute += "abcd";
  const fs::path file = dir / "huge_attribute.exr";
  put(file, bytes.substr(0, 8) + attribute + bytes.substr(8));
  const std::string expected = file.string() + ": header attribute 'note' (string) declares 2147483647 bytes, more than the ";
  for (int which = 0; which < 2; ++which) {
    try {
      if (which == 0) scenes::io::exr_channel_names(file);
      else scenes::io::read_exr_map(file);
      FAIL() << "no exception";
    } catch (const IoError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
    }
  }
}

// Found by fuzz_exr_map's campaign: a preview attribute declaring 2³² − 1 × 2³² − 1 pixels overflowed the size
// computation (4 · w · h in 64-bit signed arithmetic, undefined behaviour under UBSan) before the check against
// the file. It is refused naming the preview's size; a smaller impossible preview names its byte count.
TEST(IoExr, APreviewLargerThanTheFileIsRefusedWithoutOverflow) {
  const fs::path dir = testsupport::temp_dir("io_exr_huge_preview");
  const std::string bytes = small_map_bytes(dir);
  auto preview = [&](uint32_t w, uint32_t h) {
    std::string a = std::string("thumb\0preview\0", 14);
    const uint32_t size = 8;
    a.append(reinterpret_cast<const char*>(&size), 4);
    a.append(reinterpret_cast<const char*>(&w), 4);
    a.append(reinterpret_cast<const char*>(&h), 4);
    const fs::path file = dir / ("preview_" + std::to_string(w) + "x" + std::to_string(h) + ".exr");
    put(file, bytes.substr(0, 8) + a + bytes.substr(8));
    try {
      scenes::io::exr_channel_names(file);
    } catch (const IoError& e) {
      return std::string(e.what()).substr(file.string().size());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(preview(0xffffffffu, 0xffffffffu).rfind(": header attribute 'thumb' (preview) declares a 4294967295 x "
                                                    "4294967295 preview, more than the ", 0), 0u);
  EXPECT_EQ(preview(1000, 1000).rfind(": header attribute 'thumb' (preview) declares 4000008 bytes, more than the ", 0),
            0u);
}

// A data window wider than any map (100000 × 4) over a file of a few hundred bytes: OpenEXR refuses it from
// the header, under the 65536-a-side limit check_exr_header sets (read_exr_map's own check, 65536 a side and
// 2^30 values, stands behind it for files whose line-offset table holds up).
TEST(IoExr, ADataWindowWiderThanAnyMapIsRefusedFromTheHeader) {
  const fs::path dir = testsupport::temp_dir("io_exr_huge_window");
  std::string bytes = small_map_bytes(dir);
  const std::string key("dataWindow\0box2i\0", 17);
  const size_t at = bytes.find(key);
  ASSERT_NE(at, std::string::npos);
  const int32_t box[4] = {0, 0, 99999, 3};
  bytes.replace(at + key.size() + 4, 16, reinterpret_cast<const char*>(box), 16);
  const fs::path file = dir / "huge_window.exr";
  put(file, bytes);
  try {
    scenes::io::read_exr_map(file);
    FAIL() << "no exception";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
    EXPECT_THAT(e.what(), ::testing::HasSubstr("exceeds the maximum width")) << e.what();
  }
}

}  // namespace exr_header_tests
