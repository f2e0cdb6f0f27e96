#include "io/movie_encoder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

bool has(const std::vector<std::string>& arguments, const std::string& flag,
         const std::string& value) {
  for (std::size_t i = 0; i + 1 < arguments.size(); ++i) {
    if (arguments[i] == flag && arguments[i + 1] == value) {
      return true;
    }
  }
  return false;
}

TEST(MovieEncoder, AsksForH264InYuv420pAtTheSceneRateFromRawFramesOnItsInput) {
  const MovieRequest request{1280, 720, 25.0, "out/demo.mp4"};
  const std::vector<std::string> arguments = ffmpeg_arguments(request, "out/demo.mp4.part");
  EXPECT_EQ(arguments.front(), "ffmpeg");
  EXPECT_TRUE(has(arguments, "-f", "rawvideo"));
  EXPECT_TRUE(has(arguments, "-pix_fmt", "rgba"));
  EXPECT_TRUE(has(arguments, "-video_size", "1280x720"));
  EXPECT_TRUE(has(arguments, "-framerate", "25"));
  EXPECT_TRUE(has(arguments, "-i", "pipe:0"));
  EXPECT_TRUE(has(arguments, "-c:v", "libx264"));
  EXPECT_TRUE(has(arguments, "-pix_fmt", "yuv420p"));
  EXPECT_EQ(arguments.back(), "out/demo.mp4.part");
}

TEST(MovieEncoder, GifUsesOnePaletteAndAnOrderedDither) {
  const MovieRequest request{320, 180, 25.0, "out/demo.gif", true};
  const std::vector<std::string> arguments = ffmpeg_arguments(request, "out/demo.gif.part");
  EXPECT_TRUE(has(arguments, "-f", "gif"));
  bool ordered = false;
  for (const std::string& argument : arguments) {
    ordered = ordered || (argument.find("palettegen") != std::string::npos &&
                          argument.find("dither=bayer") != std::string::npos);
  }
  EXPECT_TRUE(ordered);
}

// Restores PATH when the test ends, whatever happens.
class PathOverride {
 public:
  explicit PathOverride(const std::string& path) : saved_(std::getenv("PATH")) {
    setenv("PATH", path.c_str(), 1);
  }
  ~PathOverride() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

TEST(MovieEncoder, MissingFfmpegIsReportedNotThrown) {
  test::TemporaryFolder folder("movie");
  PathOverride path(folder.path().string());  // a folder with no ffmpeg in it
  EXPECT_EQ(MovieEncoder::start({2, 2, 24.0, folder.path() / "demo.mp4"}), nullptr);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4"));
}

TEST(MovieEncoder, EncodesFramesSentWhileItRuns) {
  test::TemporaryFolder folder("movie");
  const std::filesystem::path movie = folder.path() / "demo.mp4";
  const std::unique_ptr<MovieEncoder> encoder = MovieEncoder::start({16, 16, 24.0, movie});
  ASSERT_NE(encoder, nullptr);
  Image frame(16, 16);
  for (int f = 0; f < 3; ++f) {
    std::fill(frame.rgba.begin(), frame.rgba.end(), static_cast<std::uint8_t>(80 * f));
    encoder->add_frame(frame);
  }
  encoder->finish();
  EXPECT_GT(std::filesystem::file_size(movie), 0U);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4.part"));
}

TEST(MovieEncoder, FailingFfmpegIsAnErrorWithItsMessageAndLeavesNoMovie) {
  test::TemporaryFolder folder("movie");
  // ffmpeg refuses a frame rate of 0 and exits; the frame sent after that is dropped.
  const std::unique_ptr<MovieEncoder> encoder =
      MovieEncoder::start({2, 2, 0.0, folder.path() / "demo.mp4"});
  ASSERT_NE(encoder, nullptr);
  encoder->add_frame(Image(2, 2));
  try {
    encoder->finish();
    FAIL() << "ffmpeg succeeded at 0 frames per second";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg failed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rate"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4.part"));
}

TEST(MovieEncoder, AnUnfinishedMovieIsStoppedAndRemoved) {
  test::TemporaryFolder folder("movie");
  {
    const std::unique_ptr<MovieEncoder> encoder =
        MovieEncoder::start({16, 16, 24.0, folder.path() / "demo.mp4"});
    ASSERT_NE(encoder, nullptr);
    encoder->add_frame(Image(16, 16));
  }  // as when drawing fails half-way
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4.part"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4.ffmpeg-log"));
}

}  // namespace
}  // namespace dinam
