#include "io/image_compare.hpp"

#include <gtest/gtest.h>

namespace dinam {
namespace {

// A 320 × 180 picture of a grey background with a dark vertical bar 6 pixels wide at `x`.
Image bar_picture(int x, std::uint8_t red = 40) {
  Image image(320, 180);
  for (int y = 0; y < 180; ++y) {
    for (int i = 0; i < 320; ++i) {
      std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * 320 + i) * 4;
      const bool bar = i >= x && i < x + 6 && y > 20 && y < 160;
      p[0] = bar ? red : 200;
      p[1] = bar ? 40 : 205;
      p[2] = bar ? 40 : 210;
      p[3] = 255;
    }
  }
  return image;
}

const ImageTolerance kDefault;

TEST(ImageCompare, IdenticalPicturesMatch) {
  const ImageComparison c = compare_images(bar_picture(100), bar_picture(100), kDefault.threshold);
  EXPECT_TRUE(c.matches(kDefault));
  EXPECT_EQ(c.differing_fraction, 0.0);
  EXPECT_EQ(c.mean_error, 0.0);
}

TEST(ImageCompare, BarMovedByAFewPixelsDoesNotMatch) {
  // 3 px × 139 rows change at each side: 834 of 57 600 pixels, 1.4 %, over the 0.5 % allowed.
  const ImageComparison c = compare_images(bar_picture(103), bar_picture(100), kDefault.threshold);
  EXPECT_FALSE(c.matches(kDefault));
  EXPECT_NEAR(c.differing_fraction, 834.0 / 57600.0, 1e-12);
  // The difference image marks exactly the changed pixels in red.
  EXPECT_EQ(c.difference.pixel(101, 90)[0], 255);
  EXPECT_EQ(c.difference.pixel(101, 90)[1], 0);
  EXPECT_NE(c.difference.pixel(50, 90)[1], 0);
}

TEST(ImageCompare, ChangedColourDoesNotMatch) {
  const ImageComparison c =
      compare_images(bar_picture(100, 200), bar_picture(100, 40), kDefault.threshold);
  EXPECT_FALSE(c.matches(kDefault));
}

TEST(ImageCompare, RenderingNoiseWithinTheToleranceMatches) {
  // Anti-aliasing rounding: a few edge pixels off by a little, one off by a lot.
  Image noisy = bar_picture(100);
  for (int y = 21; y < 160; y += 7) {
    noisy.rgba[(static_cast<std::size_t>(y) * 320 + 99) * 4] += 10;
  }
  noisy.rgba[(static_cast<std::size_t>(50) * 320 + 10) * 4] = 0;
  EXPECT_TRUE(compare_images(noisy, bar_picture(100), kDefault.threshold).matches(kDefault));
}

TEST(ImageCompare, DifferentSizesDoNotMatch) {
  Image small(160, 90);
  const ImageComparison c = compare_images(small, bar_picture(100), kDefault.threshold);
  EXPECT_FALSE(c.same_size);
  EXPECT_FALSE(c.matches(kDefault));
}

}  // namespace
}  // namespace dinam
