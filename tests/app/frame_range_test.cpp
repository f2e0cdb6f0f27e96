#include "run/frame_range.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace dinam {
namespace {

TEST(FrameRange, ParsesRangesAndSingleFrames) {
  const FrameRange range = parse_frame_range("3-7", 10);
  EXPECT_EQ(range.first, 3);
  EXPECT_EQ(range.last, 7);
  EXPECT_EQ(range.count(), 5);
  EXPECT_EQ(parse_frame_range("10", 10).count(), 1);
}

TEST(FrameRange, RejectsMalformedAndOutOfRange) {
  for (const char* bad : {"", "a-b", "3-", "-3", "0-2", "5-3", "1-11", "2.5"}) {
    EXPECT_THROW(parse_frame_range(bad, 10), UserError) << bad;
  }
}

TEST(ImageSize, ParsesWidthByHeight) {
  int width = 0;
  int height = 0;
  parse_image_size("320x180", width, height);
  EXPECT_EQ(width, 320);
  EXPECT_EQ(height, 180);
  for (const char* bad : {"320", "320x", "x180", "8x8", "320X180", "99999x10"}) {
    EXPECT_THROW(parse_image_size(bad, width, height), UserError) << bad;
  }
}

}  // namespace
}  // namespace dinam
