#include "io/png_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "core/error.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Image gradient(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>(x + y);
      p[3] = 255;
    }
  }
  return image;
}

TEST(PngFile, RoundTripKeepsEveryPixelAndLeavesNoTemporaryFile) {
  test::TemporaryFolder folder("png");
  const Image image = gradient(33, 17);  // odd sizes catch row-stride mistakes
  for (const PngOptions options : {PngOptions{}, PngOptions{9, true}}) {
    write_png(folder.path() / "frame.png", image, options);
    const Image back = read_png(folder.path() / "frame.png");
    EXPECT_EQ(back.width, 33);
    EXPECT_EQ(back.height, 17);
    EXPECT_EQ(back.rgba, image.rgba);
  }
  EXPECT_TRUE(test::temporary_files_in(folder.path()).empty());
}

// Frames say they are sRGB (an sRGB chunk, with gAMA for older readers), before the pixels, so
// that a compositor or browser does not guess another encoding.
TEST(PngFile, FramesAreTaggedSrgbBeforeTheirPixels) {
  test::TemporaryFolder folder("png");
  write_png(folder.path() / "frame.png", gradient(8, 8));
  std::ifstream file(folder.path() / "frame.png", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t srgb = bytes.find("sRGB");
  const std::size_t gama = bytes.find("gAMA");
  const std::size_t pixels = bytes.find("IDAT");
  ASSERT_NE(pixels, std::string::npos);
  EXPECT_LT(srgb, pixels);
  EXPECT_LT(gama, pixels);
}

TEST(PngFile, UnwritablePathIsAnErrorAndLeavesNothing) {
  test::TemporaryFolder folder("png");
  const auto path = folder.path() / "missing_folder" / "frame.png";
  EXPECT_THROW(write_png(path, gradient(4, 4)), RuntimeError);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(PngFile, ReadingSomethingElseIsAnError) {
  EXPECT_THROW(read_png(test::data_dir() / "cube.obj"), RuntimeError);
}

}  // namespace
}  // namespace dinam
