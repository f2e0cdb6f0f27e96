#include "io/movie_encoder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>

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
  const std::vector<std::string> arguments = ffmpeg_arguments(request, "/work/out/demo.mp4.part");
  EXPECT_EQ(arguments.front(), "ffmpeg");
  EXPECT_TRUE(has(arguments, "-f", "rawvideo"));
  EXPECT_TRUE(has(arguments, "-pix_fmt", "rgba"));
  EXPECT_TRUE(has(arguments, "-video_size", "1280x720"));
  EXPECT_TRUE(has(arguments, "-framerate", "25"));
  EXPECT_TRUE(has(arguments, "-i", "pipe:0"));
  EXPECT_TRUE(has(arguments, "-c:v", "libx264"));
  EXPECT_TRUE(has(arguments, "-pix_fmt", "yuv420p"));
}

// Whatever the name, ffmpeg reads it as a local file: absolute and after "file:", so a leading
// dash is no option and "tcp://" or "concat:" no protocol; the input may be the pipe alone.
TEST(MovieEncoder, GivesFfmpegAFileAndNothingElse) {
  for (const char* name :
       {"/w/-y/demo.mp4.part.1", "/w/tcp:/127.0.0.1:9/demo.gif.part.2", "/w/concat:a|b.part.3"}) {
    const std::vector<std::string> arguments = ffmpeg_arguments({16, 16, 24.0, "demo.mp4"}, name);
    EXPECT_EQ(arguments.back(), std::string("file:") + name);
    EXPECT_TRUE(has(arguments, "-protocol_whitelist", "pipe"));
    EXPECT_TRUE(has(arguments, "-protocol_whitelist", "file"));
    EXPECT_EQ(std::count(arguments.begin(), arguments.end(), "-i"), 1);
  }
}

TEST(MovieEncoder, GifUsesOnePaletteAndAnOrderedDither) {
  const MovieRequest request{320, 180, 25.0, "out/demo.gif", true};
  const std::vector<std::string> arguments = ffmpeg_arguments(request, "/work/out/demo.gif.part");
  EXPECT_TRUE(has(arguments, "-f", "gif"));
  bool ordered = false;
  for (const std::string& argument : arguments) {
    ordered = ordered || (argument.find("palettegen") != std::string::npos &&
                          argument.find("dither=bayer") != std::string::npos);
  }
  EXPECT_TRUE(ordered);
}

// Sets an environment variable for the test's span, restoring it (or its absence) after.
class EnvironmentOverride {
 public:
  EnvironmentOverride(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) {
      saved_ = old;
    }
    setenv(name, value.c_str(), 1);
  }
  ~EnvironmentOverride() {
    if (saved_) {
      setenv(name_, saved_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  EnvironmentOverride(const EnvironmentOverride&) = delete;
  EnvironmentOverride& operator=(const EnvironmentOverride&) = delete;

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

TEST(MovieEncoder, MissingFfmpegIsReportedNotThrown) {
  test::TemporaryFolder folder("movie");
  const EnvironmentOverride path("PATH", folder.path().string());  // a folder with no ffmpeg
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
  EXPECT_EQ(test::folder_entries(folder.path()), std::vector<std::string>{"demo.mp4"});
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
  EXPECT_TRUE(test::folder_entries(folder.path()).empty());
}

TEST(MovieEncoder, AnUnfinishedMovieIsStoppedAndRemoved) {
  test::TemporaryFolder folder("movie");
  {
    const std::unique_ptr<MovieEncoder> encoder =
        MovieEncoder::start({16, 16, 24.0, folder.path() / "demo.mp4"});
    ASSERT_NE(encoder, nullptr);
    encoder->add_frame(Image(16, 16));
  }  // as when drawing fails half-way
  EXPECT_TRUE(test::folder_entries(folder.path()).empty());
}

// A stand-in ffmpeg that never reads its input and never exits: the frames fill the pipe, and
// after DINAM_FFMPEG_TIMEOUT seconds without a byte taken or CPU used it is stopped, with a
// message, and nothing is left. The frame is larger than any pipe's buffer.
TEST(MovieEncoder, AnFfmpegThatNeverReadsIsStoppedAfterItsTimeout) {
  const test::TemporaryFolder folder("movie");
  const test::TemporaryFolder tools("stand-in");
  const std::filesystem::path stand_in = tools.path() / "ffmpeg";
  std::ofstream(stand_in) << "#!/bin/sh\nexec sleep 600\n";
  std::filesystem::permissions(stand_in, std::filesystem::perms::owner_all);
  const EnvironmentOverride program("DINAM_FFMPEG", stand_in.string());
  const EnvironmentOverride timeout("DINAM_FFMPEG_TIMEOUT", "1");
  const std::unique_ptr<MovieEncoder> encoder =
      MovieEncoder::start({1024, 1024, 24.0, folder.path() / "demo.mp4"});
  ASSERT_NE(encoder, nullptr);
  try {
    encoder->add_frame(Image(1024, 1024));
    FAIL() << "a 4 MB frame went into a pipe nobody reads";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("took no frame data and used no CPU"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("DINAM_FFMPEG_TIMEOUT"), std::string::npos) << e.what();
  }
  // It gave up: a wait for ever would have held the test until ctest's own limit. How soon is
  // the machine's business, so nothing is asserted on a clock.
  EXPECT_TRUE(test::folder_entries(folder.path()).empty());
}

TEST(MovieEncoder, ATimeoutThatIsNotAPositiveNumberIsRefused) {
  for (const char* text : {"soon", "0", "-5", "nan"}) {
    const EnvironmentOverride timeout("DINAM_FFMPEG_TIMEOUT", text);
    test::expect_user_error([] { ffmpeg_stall_seconds(); }, 0,
                            {"DINAM_FFMPEG_TIMEOUT", "positive number"});
  }
}

}  // namespace
}  // namespace dinam
