#include "io/movie_encoder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>

#include "core/thread_team.hpp"
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
  // The process's thread count, not every CPU of the machine.
  set_thread_count(3);
  EXPECT_TRUE(has(ffmpeg_arguments(request, "/work/out/demo.mp4.part"), "-threads", "3"));
  set_thread_count(1);
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

// The movie says it is BT.709 (matrix, primaries, transfer; limited range), and is: ffmpeg, which
// reads those tags, turns a frame of strong colours back into RGB within the rounding of 8-bit
// YUV 4:2:0 of a flat picture (±3 of 255). With the matrix of BT.601 (ffmpeg's default) under
// BT.709's tags, the colours would come back up to 23 off (the green of the second quarter).
TEST(MovieEncoder, TheMovieIsTaggedBt709AndDecodesToItsColours) {
  if (test::run_command("command -v ffprobe").output.empty()) {
    GTEST_SKIP() << "ffprobe is not installed";
  }
  test::TemporaryFolder folder("movie");
  const std::filesystem::path movie = folder.path() / "colours.mp4";
  const std::unique_ptr<MovieEncoder> encoder = MovieEncoder::start({64, 64, 24.0, movie});
  ASSERT_NE(encoder, nullptr);
  Image frame(64, 64);
  const std::array<std::array<std::uint8_t, 3>, 4> colours{
      {{200, 30, 30}, {30, 180, 60}, {40, 60, 220}, {235, 235, 235}}};
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const auto& c = colours[static_cast<std::size_t>((y / 32) * 2 + x / 32)];
      const std::size_t at = 4 * static_cast<std::size_t>(y * 64 + x);
      frame.rgba[at] = c[0];
      frame.rgba[at + 1] = c[1];
      frame.rgba[at + 2] = c[2];
      frame.rgba[at + 3] = 255;
    }
  }
  for (int f = 0; f < 3; ++f) {
    encoder->add_frame(frame);
  }
  encoder->finish();
  const test::CommandResult probe = test::run_command(
      "ffprobe -v error -select_streams v:0 -show_entries "
      "stream=color_space,color_transfer,color_primaries,color_range -of default=nw=1 '" +
      movie.string() + "'");
  test::expect_contains(probe.output, {"color_range=tv", "color_space=bt709",
                                       "color_transfer=bt709", "color_primaries=bt709"});
  const std::filesystem::path decoded = folder.path() / "decoded.png";
  const test::CommandResult decode =
      test::run_command("ffmpeg -v error -i '" + movie.string() +
                        "' -frames:v 1 -vf scale=in_color_matrix=auto '" + decoded.string() + "'");
  ASSERT_EQ(decode.exit_code, 0) << decode.output;
  const Image back = read_png(decoded);
  for (std::size_t q = 0; q < colours.size(); ++q) {
    const int x = 16 + 32 * static_cast<int>(q % 2);  // the middle of each quarter
    const int y = 16 + 32 * static_cast<int>(q / 2);
    for (int c = 0; c < 3; ++c) {
      const int got =
          back.rgba[4 * static_cast<std::size_t>(y * 64 + x) + static_cast<std::size_t>(c)];
      EXPECT_NEAR(got, colours[q][static_cast<std::size_t>(c)], 3)
          << "quarter " << q << " channel " << c;
    }
  }
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
