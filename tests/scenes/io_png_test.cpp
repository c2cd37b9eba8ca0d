// PNG frames: top row first on disk, 8-bit sRGB (bytes of an sRGB target unchanged, linear targets encoded),
// written through a temporary file.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "raster/target.h"
#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "scenes/io/png_frame.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

// Reads a PNG with OpenImageIO as it is on disk (top row first, alpha not premultiplied into colour).
std::vector<uint8_t> read_raw(const fs::path& file, int& w, int& h, int& n) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(file.string(), &config);
  EXPECT_TRUE(in);
  if (!in) return {};
  w = in->spec().width;
  h = in->spec().height;
  n = in->spec().nchannels;
  std::vector<uint8_t> px(size_t(w) * size_t(h) * size_t(n));
  EXPECT_TRUE(in->read_image(0, 0, 0, n, OIIO::TypeDesc::UINT8, px.data()));
  return px;
}

// The sRGB encoding, written out independently of raster::srgb_encode.
uint8_t srgb_byte(double linear) {
  const double e = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return uint8_t(std::lround(e * 255.0));
}

TEST(IoPng, SrgbTargetBytesAreWrittenTopRowFirst) {
  const fs::path dir = testsupport::temp_dir("io_png_rows");
  raster::ColorTarget target(3, 2, raster::ColorFormat::rgba8, true);
  // Every pixel different: stored bytes (10·x + 100·y + c) for channel c.
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c) target.row8(y)[x * 4 + c] = uint8_t(10 * x + 100 * y + c);
  scenes::io::write_png(dir / "frame.png", target);
  int w = 0, h = 0, n = 0;
  const std::vector<uint8_t> px = read_raw(dir / "frame.png", w, h, n);
  ASSERT_EQ(w, 3);
  ASSERT_EQ(h, 2);
  ASSERT_EQ(n, 3);
  // File row 0 is the target's top row (y = 1).
  for (int r = 0; r < 2; ++r)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(px[size_t((r * 3 + x) * 3 + c)], uint8_t(10 * x + 100 * (1 - r) + c)) << r << x << c;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(IoPng, LinearTargetsAreSrgbEncoded) {
  const fs::path dir = testsupport::temp_dir("io_png_linear");
  raster::ColorTarget lin8(2, 1, raster::ColorFormat::rgba8, false);
  lin8.row8(0)[0] = 128;  // linear 128/255
  lin8.row8(0)[1] = 0;
  lin8.row8(0)[2] = 255;
  lin8.row8(0)[3] = 77;
  scenes::io::write_png(dir / "lin8.png", lin8, true);
  int w, h, n;
  std::vector<uint8_t> px = read_raw(dir / "lin8.png", w, h, n);
  ASSERT_EQ(n, 4);
  EXPECT_EQ(px[0], srgb_byte(128.0 / 255.0));
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[2], 255);
  EXPECT_EQ(px[3], 77);  // alpha unchanged

  raster::ColorTarget f32(2, 1, raster::ColorFormat::rgba32f);
  f32.write(0, 0, glm::vec4(0.5f, 2.0f, -1.0f, 0.5f));
  f32.write(1, 0, glm::vec4(0.002f, 0.2f, 1.0f, 1.0f));
  scenes::io::write_png(dir / "f32.png", f32);
  px = read_raw(dir / "f32.png", w, h, n);
  ASSERT_EQ(n, 3);
  EXPECT_EQ(px[0], 188);  // sRGB(0.5) · 255 = 187.52
  EXPECT_EQ(px[1], 255);  // clamped
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(px[3], srgb_byte(0.002));  // the linear segment: 12.92 · 0.002 · 255 = 6.59 → 7
  EXPECT_EQ(px[4], srgb_byte(0.2));
  EXPECT_EQ(px[5], 255);
}

TEST(IoPng, FailedWritesLeaveNoFile) {
  const fs::path dir = testsupport::temp_dir("io_png_fail");
  raster::ColorTarget target(2, 2, raster::ColorFormat::rgba8, true);
  // A directory where the file should go: the PNG is written under its temporary name, the rename fails.
  fs::create_directory(dir / "frame.png");
  try {
    scenes::io::write_png(dir / "frame.png", target);
    FAIL() << "no exception";
  } catch (const scenes::io::IoError& e) {
    EXPECT_EQ(e.file(), dir / "frame.png");
    EXPECT_EQ(std::string(e.what()).rfind((dir / "frame.png").string() + ": ", 0), 0u) << e.what();
  }
  EXPECT_THROW(scenes::io::write_png(dir / "missing" / "frame.png", target), scenes::io::IoError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);  // the directory alone
}

// Issue 23: on a full disk the PNG path exited 0 with a truncated file. Every byte is now written through
// write_bytes, which checks each write and the flush: /dev/full (always "no space left") makes it throw.
TEST(IoPng, AFullDiskIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "skipped: /dev/full not available";
  const std::vector<unsigned char> bytes(100000, 7);
  try {
    scenes::io::write_bytes("/dev/full", bytes.data(), bytes.size());
    FAIL() << "no exception";
  } catch (const scenes::io::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
}

// Issue 23: a killed run leaves its temporary file; the next write beside it removes temporaries of processes
// that no longer run, and keeps those of live ones.
TEST(IoPng, TemporariesOfDeadRunsAreRemoved) {
  const fs::path dir = testsupport::temp_dir("io_png_stale");
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  ::waitpid(child, &status, 0);  // its pid now names no process
  const fs::path dead = dir / (".frame.tmp-" + std::to_string(child) + "-0.png");
  const fs::path live = dir / (".frame.tmp-" + std::to_string(::getppid()) + "-3.png");
  const fs::path other = dir / ".other.tmp-1-0.png";
  for (const fs::path& p : {dead, live, other}) std::ofstream(p) << "partial";
  raster::ColorTarget target(2, 2, raster::ColorFormat::rgba8, true);
  scenes::io::write_png(dir / "frame.png", target);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));  // another file's temporaries are left to its own writes
  EXPECT_TRUE(fs::exists(dir / "frame.png"));
}

}  // namespace
