// Error maps and contact sheets: which colour each kind of error gets, the frame darkened to grey elsewhere, and
// the sheet's halves (the frame as it was, then its error map).
#include <gtest/gtest.h>

#include "scenes/reference/error_map.h"
#include "scenes/reference/shadow_score.h"

namespace {

TEST(ErrorMap, ColoursPerErrorAndGreyElsewhere) {
  raster::ColorTarget frame(4, 2, raster::ColorFormat::rgba8);
  frame.clear(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));  // a red frame turns grey, so red means an error
  std::vector<uint8_t> errors(8, 0);
  errors[1] = reference::kFalseShadowed;
  errors[2] = reference::kFalseLit;
  errors[5] = reference::kFalseShadowed | reference::kFalseLit;
  const raster::ColorTarget m = reference::error_map(frame, errors);
  const glm::vec4 grey = m.read(0, 0);
  EXPECT_EQ(grey.r, grey.g);
  EXPECT_EQ(grey.g, grey.b);
  EXPECT_LT(grey.r, 0.1f);
  EXPECT_EQ(m.read(1, 0), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_GT(m.read(2, 0).b, 0.99f);
  EXPECT_LT(m.read(2, 0).r, 0.2f);
  EXPECT_EQ(m.read(1, 1), glm::vec4(1.0f, 0.0f, 1.0f, 1.0f));
  EXPECT_THROW(reference::error_map(frame, std::vector<uint8_t>(7, 0)), reference::ReferenceError);
}

TEST(ErrorMap, ContactSheetIsFrameThenMap) {
  raster::ColorTarget frame(3, 2, raster::ColorFormat::rgba8);
  frame.clear(glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  std::vector<uint8_t> errors(6, 0);
  errors[4] = reference::kFalseShadowed;  // (1, 1)
  const raster::ColorTarget s = reference::contact_sheet(frame, errors);
  ASSERT_EQ(s.width(), 6);
  ASSERT_EQ(s.height(), 2);
  EXPECT_EQ(s.read(1, 1), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  EXPECT_EQ(s.read(4, 1), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_LT(s.read(3, 0).g, 0.2f);
  raster::ColorTarget heat(3, 2, raster::ColorFormat::rgba8);
  heat.clear(glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
  const raster::ColorTarget three = reference::contact_sheet(frame, errors, &heat);
  ASSERT_EQ(three.width(), 9);
  EXPECT_EQ(three.read(7, 0), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
  const raster::ColorTarget small(2, 2, raster::ColorFormat::rgba8);
  EXPECT_THROW(reference::contact_sheet(frame, errors, &small), reference::ReferenceError);
}

}  // namespace
