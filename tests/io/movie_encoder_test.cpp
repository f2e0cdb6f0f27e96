#include "io/movie_encoder.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

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

TEST(MovieEncoder, AsksForH264InYuv420pAtTheSceneRate) {
  const MovieRequest request{"out/frame_%04d.png", 5, 20, 25.0, "out/demo.mp4"};
  const std::vector<std::string> arguments = ffmpeg_arguments(request, "out/demo.mp4.part");
  EXPECT_EQ(arguments.front(), "ffmpeg");
  EXPECT_TRUE(has(arguments, "-c:v", "libx264"));
  EXPECT_TRUE(has(arguments, "-pix_fmt", "yuv420p"));
  EXPECT_TRUE(has(arguments, "-framerate", "25"));
  EXPECT_TRUE(has(arguments, "-start_number", "5"));
  EXPECT_TRUE(has(arguments, "-frames:v", "20"));
  EXPECT_EQ(arguments.back(), "out/demo.mp4.part");
}

TEST(MovieEncoder, GifUsesOnePaletteAndAnOrderedDither) {
  MovieRequest request{"out/frame_%04d.png", 1, 20, 25.0, "out/demo.gif", true};
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
  const MovieRequest request{folder.path() / "frame_%04d.png", 1, 1, 24.0,
                             folder.path() / "demo.mp4"};
  EXPECT_EQ(encode_movie(request), MovieOutcome::kFfmpegMissing);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4"));
}

TEST(MovieEncoder, FailingFfmpegIsAnErrorWithItsMessageAndLeavesNoMovie) {
  test::TemporaryFolder folder("movie");
  // No frames exist, so ffmpeg fails to open its input.
  const MovieRequest request{folder.path() / "frame_%04d.png", 1, 3, 24.0,
                             folder.path() / "demo.mp4"};
  try {
    encode_movie(request);
    FAIL() << "ffmpeg succeeded without frames";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg failed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "demo.mp4.part"));
}

}  // namespace
}  // namespace dinam
