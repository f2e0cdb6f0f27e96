#include "io/image_compare.hpp"

#include <gtest/gtest.h>

#include <vector>

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
  const ImageComparison c = compare_images(bar_picture(100), bar_picture(100), kDefault);
  EXPECT_TRUE(c.matches(kDefault));
  EXPECT_EQ(c.differing_fraction, 0.0);
  EXPECT_EQ(c.mean_error, 0.0);
}

TEST(ImageCompare, BarMovedByAFewPixelsDoesNotMatch) {
  // Compared pixel by pixel (no shift allowed): 3 px × 139 rows change at each side, 834 of
  // 57 600 pixels, 1.4 %, over the 0.5 % allowed.
  ImageTolerance exact = kDefault;
  exact.shift = 0;
  const ImageComparison c = compare_images(bar_picture(103), bar_picture(100), exact);
  EXPECT_FALSE(c.matches(exact));
  EXPECT_NEAR(c.differing_fraction, 834.0 / 57600.0, 1e-12);
  // Allowing an edge to move by a pixel, a pixel whose neighbours on either picture hold only the
  // other colour still differs: three columns at each side (830 of 57 600: the bar's first and
  // last rows see the background above and below), and the structure is not the same.
  const ImageComparison shifted = compare_images(bar_picture(103), bar_picture(100), kDefault);
  EXPECT_FALSE(shifted.matches(kDefault));
  EXPECT_NEAR(shifted.differing_fraction, 830.0 / 57600.0, 1e-12);
  EXPECT_LT(shifted.ssim, 0.97);
  // The difference image marks exactly the changed pixels in red.
  EXPECT_EQ(c.difference.pixel(101, 90)[0], 255);
  EXPECT_EQ(c.difference.pixel(101, 90)[1], 0);
  EXPECT_NE(c.difference.pixel(50, 90)[1], 0);
}

TEST(ImageCompare, ChangedColourDoesNotMatch) {
  const ImageComparison c = compare_images(bar_picture(100, 200), bar_picture(100, 40), kDefault);
  EXPECT_FALSE(c.matches(kDefault));
}

TEST(ImageCompare, RenderingNoiseWithinTheToleranceMatches) {
  // Anti-aliasing rounding: a few edge pixels off by a little, one off by a lot.
  Image noisy = bar_picture(100);
  for (int y = 21; y < 160; y += 7) {
    noisy.rgba[(static_cast<std::size_t>(y) * 320 + 99) * 4] += 10;
  }
  noisy.rgba[(static_cast<std::size_t>(50) * 320 + 10) * 4] = 0;
  EXPECT_TRUE(compare_images(noisy, bar_picture(100), kDefault).matches(kDefault));
}

// A bar whose edges moved by half a pixel: the edge columns take blends of the bar and the
// background, values their neighbours span, so no pixel differs; the structure is the same.
TEST(ImageCompare, AnEdgeMovedByHalfAPixelMatches) {
  const Image original = bar_picture(100);
  Image moved = original;
  const std::uint8_t* bar = original.pixel(101, 90);
  const std::uint8_t* ground = original.pixel(10, 90);
  for (int y = 21; y < 160; ++y) {
    for (const int x : {100, 106}) {
      std::uint8_t* p = moved.rgba.data() + (static_cast<std::size_t>(y) * 320 + x) * 4;
      for (int c = 0; c < 3; ++c) {
        p[c] = static_cast<std::uint8_t>((int{bar[c]} + int{ground[c]}) / 2);
      }
    }
  }
  const ImageComparison c = compare_images(moved, bar_picture(100), kDefault);
  EXPECT_EQ(c.differing_fraction, 0.0);
  EXPECT_GT(c.ssim, 0.98);
  EXPECT_TRUE(c.matches(kDefault)) << c.failures(kDefault);
  // Compared pixel by pixel the two edge columns differ (278 pixels, 0.48 %).
  ImageTolerance exact = kDefault;
  exact.shift = 0;
  EXPECT_NEAR(compare_images(moved, bar_picture(100), exact).differing_fraction, 278.0 / 57600.0,
              1e-12);
}

TEST(ImageCompare, SsimIsOneForTheSamePictureAndFallsWithAChange) {
  EXPECT_NEAR(structural_similarity(bar_picture(100), bar_picture(100)), 1.0, 1e-12);
  const double moved = structural_similarity(bar_picture(110), bar_picture(100));
  EXPECT_LT(moved, 0.95);
  EXPECT_GT(moved, 0.5);  // most of the picture is the same background
}

// Weights: a region left out (0) is in no measure; one weighed more counts more.
TEST(ImageCompare, RegionsLeftOutOrWeighedMore) {
  std::vector<float> weights(320 * 180, 1.0f);
  for (int y = 0; y < 180; ++y) {
    for (int x = 90; x < 120; ++x) {
      weights[static_cast<std::size_t>(y) * 320 + x] = 0.0f;
    }
  }
  // The bar moved within the masked columns: no measure sees it.
  const ImageComparison masked =
      compare_images(bar_picture(103), bar_picture(100), kDefault, weights);
  EXPECT_EQ(masked.differing_fraction, 0.0);
  EXPECT_EQ(masked.mean_error, 0.0);
  EXPECT_TRUE(masked.matches(kDefault));
  EXPECT_EQ(masked.difference.pixel(101, 90)[2], 90);  // drawn dark blue
  // The same move, its columns weighed four times: the differing share grows.
  std::vector<float> heavy(320 * 180, 1.0f);
  for (int y = 0; y < 180; ++y) {
    for (int x = 90; x < 120; ++x) {
      heavy[static_cast<std::size_t>(y) * 320 + x] = 4.0f;
    }
  }
  const double plain =
      compare_images(bar_picture(103), bar_picture(100), kDefault).differing_fraction;
  const double weighed =
      compare_images(bar_picture(103), bar_picture(100), kDefault, heavy).differing_fraction;
  // 830 pixels × 4 over 57 600 + 3 × 30 × 180 weight.
  EXPECT_NEAR(weighed, 4.0 * 830.0 / (57600.0 + 3.0 * 30.0 * 180.0), 1e-12);
  EXPECT_GT(weighed, 3.0 * plain);
}

TEST(ImageCompare, DifferentSizesDoNotMatch) {
  Image small(160, 90);
  const ImageComparison c = compare_images(small, bar_picture(100), kDefault);
  EXPECT_FALSE(c.same_size);
  EXPECT_FALSE(c.matches(kDefault));
}

}  // namespace
}  // namespace dinam
