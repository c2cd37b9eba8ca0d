// Multi-channel EXR images (the per-pixel surface record's file): written and read back bit for bit, on disk top
// row first like the PNG frames (checked with OpenEXR directly), and refused with the file named when the channels
// do not fit, leaving nothing behind.
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scenes/io/exr_image.h"
#include "scenes/io/io_error.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;
using scenes::io::ExrImage;

// Channel "row" holds the GL row index, "x" the column, "w" a fraction that is not exact in decimal.
ExrImage ramp(int w, int h) {
  ExrImage img{w, h, {{"row", {}}, {"x", {}}, {"light0.V", {}}}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.channels[0].values.push_back(float(y));
      img.channels[1].values.push_back(float(x));
      img.channels[2].values.push_back(float(x + 7 * y) / 3.0f);
    }
  return img;
}

TEST(ExrImage, RoundTripAndTopRowFirstOnDisk) {
  const fs::path dir = testsupport::temp_dir("exr_image_round_trip");
  const ExrImage img = ramp(5, 4);
  scenes::io::write_exr_image(dir / "a.exr", img);
  const ExrImage back = scenes::io::read_exr_image(dir / "a.exr");
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 4);
  ASSERT_EQ(back.channels.size(), 3u);
  for (const auto& c : img.channels) {
    ASSERT_NE(back.find(c.name), nullptr) << c.name;
    EXPECT_EQ(back.find(c.name)->values, c.values) << c.name;
  }
  // OpenEXR's own reading: file row 0 is the GL top row (row 3).
  Imf::InputFile in((dir / "a.exr").c_str());
  std::vector<float> rows(20);
  Imf::FrameBuffer fb;
  fb.insert("row", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rows.data()), sizeof(float), 5 * sizeof(float)));
  in.setFrameBuffer(fb);
  in.readPixels(0, 3);
  EXPECT_EQ(rows[0], 3.0f);
  EXPECT_EQ(rows[19], 0.0f);
}

TEST(ExrImage, BadImagesNameTheFileAndLeaveNothing) {
  const fs::path dir = testsupport::temp_dir("exr_image_bad");
  ExrImage short_channel = ramp(5, 4);
  short_channel.channels[1].values.pop_back();
  ExrImage twice = ramp(5, 4);
  twice.channels[2].name = "x";
  ExrImage unnamed = ramp(5, 4);
  unnamed.channels[0].name.clear();
  ExrImage empty{0, 4, {}};
  for (const ExrImage* img : {&short_channel, &twice, &unnamed, &empty}) {
    try {
      scenes::io::write_exr_image(dir / "b.exr", *img);
      ADD_FAILURE() << "written";
    } catch (const scenes::io::IoError& e) {
      EXPECT_EQ(std::string(e.what()).rfind((dir / "b.exr").string() + ": ", 0), 0u) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
  }
  EXPECT_THROW(scenes::io::read_exr_image(dir / "missing.exr"), scenes::io::IoError);
}

}  // namespace
