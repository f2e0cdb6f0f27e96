// Simulate once, render anywhere, as a user runs it: `dinam simulate`, `dinam render --cache` in
// chunks, `dinam movie`; stale caches refused (interruptions: interruption_test.cpp).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "test_support.hpp"

namespace dinam {
namespace {

using test::CommandResult;

using test::dinam_command;
using test::run_command;
using test::shell_quoted;

std::string file_text(const std::filesystem::path& path) {
  std::stringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

class CacheEndToEnd : public ::testing::Test {
 protected:
  std::filesystem::path path(const std::string& name) const { return folder_.path() / name; }
  test::TemporaryFolder folder_{"cache-e2e"};
};

const std::filesystem::path kFlag = test::data_dir() / "end_to_end_flag.yaml";

TEST_F(CacheEndToEnd, FlagInThreeChunksFromOneCacheIsTheWholeRenderByteForByte) {
  const CommandResult whole =
      run_command(dinam_command("render " + shell_quoted(kFlag) + " -o " +
                                shell_quoted(path("whole")) + " --size 96x54 --movie none -q"));
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const CommandResult simulate = run_command(dinam_command(
      "simulate " + shell_quoted(kFlag) + " -o " + shell_quoted(path("cache")) + " -q"));
  ASSERT_EQ(simulate.exit_code, 0) << simulate.output;
  for (const char* chunk : {"81-120", "1-40", "41-80"}) {  // any order, as a farm finishes them
    const CommandResult render = run_command(dinam_command(
        "render " + shell_quoted(kFlag) + " --cache " + shell_quoted(path("cache")) + " --frames " +
        chunk + " -o " + shell_quoted(path("chunks")) + " --size 96x54 --movie none -q"));
    ASSERT_EQ(render.exit_code, 0) << chunk << ": " << render.output;
  }
  for (int frame = 1; frame <= 120; ++frame) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", frame);
    const std::string expected = file_text(path("whole") / name);
    ASSERT_FALSE(expected.empty()) << name;
    ASSERT_EQ(file_text(path("chunks") / name), expected) << name << " differs";
  }

  const CommandResult movie = run_command(dinam_command("movie " + shell_quoted(path("chunks"))));
  ASSERT_EQ(movie.exit_code, 0) << movie.output;
  const CommandResult probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,nb_read_frames,r_frame_rate -of csv=p=0 " +
      shell_quoted(path("chunks") / "end_to_end_flag.mp4"));
  ASSERT_EQ(probe.exit_code, 0) << probe.output;
  EXPECT_EQ(probe.output, "h264,20/1,120\n");
}

TEST_F(CacheEndToEnd, MovieNamesMissingAndExtraFramesAndMakesNothing) {
  ASSERT_EQ(run_command(dinam_command("render " + shell_quoted(kFlag) + " -o " +
                                      shell_quoted(path("frames")) +
                                      " --size 32x18 --frames 1-120 --movie none -q"))
                .exit_code,
            0);
  std::filesystem::remove(path("frames") / "frame_0005.png");
  for (const char* name : {"frame_0041.png", "frame_0042.png", "frame_0043.png"}) {
    std::filesystem::remove(path("frames") / name);
  }
  std::filesystem::copy_file(path("frames") / "frame_0001.png", path("frames") / "frame_0121.png");
  const CommandResult movie = run_command(dinam_command("movie " + shell_quoted(path("frames"))));
  EXPECT_EQ(movie.exit_code, 2) << movie.output;
  EXPECT_NE(movie.output.find("missing frames: 5, 41-43"), std::string::npos) << movie.output;
  EXPECT_NE(movie.output.find("frame_0121.png"), std::string::npos) << movie.output;
  EXPECT_FALSE(std::filesystem::exists(path("frames") / "end_to_end_flag.mp4"));
  EXPECT_TRUE(test::temporary_files_in(path("frames")).empty());

  const CommandResult no_folder =
      run_command(dinam_command("movie " + shell_quoted(path("absent"))));
  EXPECT_EQ(no_folder.exit_code, 2);
  EXPECT_NE(no_folder.output.find("frames.json"), std::string::npos) << no_folder.output;
}

// A tiny rope scene beside the test's files, which the tests edit.
const char* const kRope = R"(version: 1
name: rope
duration: 0.5
fps: 10
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 8}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {indices: [0]}
    color: [0.1, 0.9, 0.1]
)";

TEST_F(CacheEndToEnd, AStaleCacheIsRefusedWithTheChangedKeyAndTheCommandThatMendsIt) {
  std::ofstream(path("rope.yaml")) << kRope;
  ASSERT_EQ(run_command(dinam_command("simulate " + shell_quoted(path("rope.yaml")) + " -o " +
                                      shell_quoted(path("cache")) + " -q"))
                .exit_code,
            0);
  std::string edited = kRope;
  edited.replace(edited.find("1.0e7"), 5, "2.0e7");
  std::ofstream(path("rope.yaml")) << edited;
  const CommandResult render =
      run_command(dinam_command("render " + shell_quoted(path("rope.yaml")) + " --cache " +
                                shell_quoted(path("cache")) + " -o " + shell_quoted(path("out"))));
  EXPECT_EQ(render.exit_code, 2) << render.output;
  EXPECT_NE(render.output.find("objects[0].material.youngs_modulus: 1.0e7 in the cache, 2.0e7 now"),
            std::string::npos)
      << render.output;
  EXPECT_NE(render.output.find("dinam simulate"), std::string::npos) << render.output;
  EXPECT_FALSE(std::filesystem::exists(path("out")));  // nothing written

  const CommandResult energy =
      run_command(dinam_command("render " + shell_quoted(path("rope.yaml")) + " --cache " +
                                shell_quoted(path("cache")) + " --energy"));
  EXPECT_EQ(energy.exit_code, 2);
  EXPECT_NE(energy.output.find("simulate --energy"), std::string::npos) << energy.output;
}

// A blurred scene's cache holds the instants its frames average, so frames drawn from it are the
// whole run's; a cache without them (made before the scene asked for blur) draws them unblurred,
// with the command that makes one that blurs.
TEST_F(CacheEndToEnd, BlurredFramesFromTheCacheAreTheWholeRunsAndACacheWithoutInstantsDrawsSharp) {
  std::ofstream(path("flag.yaml")) << file_text(kFlag);
  ASSERT_EQ(run_command(dinam_command("simulate " + shell_quoted(path("flag.yaml")) + " -o " +
                                      shell_quoted(path("plain_cache")) + " -q"))
                .exit_code,
            0);
  std::string blurred = file_text(kFlag);
  blurred += "image: {motion_blur: {shutter: 0.5, samples: 4}}\n";
  std::ofstream(path("flag.yaml")) << blurred;
  const std::string size = " --size 96x54 --movie none -q";
  const CommandResult whole =
      run_command(dinam_command("render " + shell_quoted(path("flag.yaml")) + " -o " +
                                shell_quoted(path("whole")) + " --frames 30-31" + size));
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  ASSERT_EQ(run_command(dinam_command("simulate " + shell_quoted(path("flag.yaml")) + " -o " +
                                      shell_quoted(path("cache")) + " -q"))
                .exit_code,
            0);
  const CommandResult chunk = run_command(dinam_command(
      "render " + shell_quoted(path("flag.yaml")) + " --cache " + shell_quoted(path("cache")) +
      " -o " + shell_quoted(path("chunk")) + " --frames 30-31" + size));
  ASSERT_EQ(chunk.exit_code, 0) << chunk.output;
  for (const char* name : {"frame_0030.png", "frame_0031.png"}) {
    const std::string expected = file_text(path("whole") / name);
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_EQ(file_text(path("chunk") / name), expected) << name << " differs";
  }

  // A cache made without instants still serves the blurred scene: its frames are drawn without
  // blur, the same as the scene without it draws them from that cache, and a warning says how to
  // have the blur.
  const CommandResult unblurred =
      run_command(dinam_command("render " + shell_quoted(path("flag.yaml")) + " --cache " +
                                shell_quoted(path("plain_cache")) + " -o " +
                                shell_quoted(path("unblurred")) + " --frames 30-31" + size));
  EXPECT_EQ(unblurred.exit_code, 0) << unblurred.output;
  EXPECT_NE(unblurred.output.find("holds no instants between frames, so its frames are drawn "
                                  "without motion blur"),
            std::string::npos)
      << unblurred.output;
  EXPECT_NE(unblurred.output.find("dinam simulate"), std::string::npos) << unblurred.output;
  std::ofstream(path("flag.yaml")) << file_text(kFlag);
  const CommandResult plain =
      run_command(dinam_command("render " + shell_quoted(path("flag.yaml")) + " --cache " +
                                shell_quoted(path("plain_cache")) + " -o " +
                                shell_quoted(path("plain")) + " --frames 30-31" + size));
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("warning"), std::string::npos) << plain.output;
  for (const char* name : {"frame_0030.png", "frame_0031.png"}) {
    const std::string expected = file_text(path("plain") / name);
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_EQ(file_text(path("unblurred") / name), expected) << name << " differs";
    // and it is not the blurred frame
    EXPECT_NE(file_text(path("whole") / name), expected) << name;
  }
}

TEST_F(CacheEndToEnd, EnergyGoesIntoTheManifestAndBesideIt) {
  std::ofstream(path("rope.yaml")) << kRope;
  const CommandResult simulate =
      run_command(dinam_command("simulate " + shell_quoted(path("rope.yaml")) + " -o " +
                                shell_quoted(path("cache")) + " --energy --format mdd -q"));
  ASSERT_EQ(simulate.exit_code, 0) << simulate.output;
  const std::string manifest = file_text(path("cache") / "manifest.json");
  EXPECT_NE(manifest.find("\"total_J\""), std::string::npos);
  EXPECT_NE(manifest.find("\"mdd\": \"rope.mdd\""), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path("cache") / "rope.pc2"));
  std::ifstream csv(path("cache") / "energy.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) {
    ++lines;
  }
  EXPECT_EQ(lines, 1 + 5);  // the header and one row per frame
  // An MDD-only cache draws as well.
  const CommandResult render = run_command(dinam_command(
      "render " + shell_quoted(path("rope.yaml")) + " --cache " + shell_quoted(path("cache")) +
      " -o " + shell_quoted(path("out")) + " --size 32x18 --movie none -q"));
  EXPECT_EQ(render.exit_code, 0) << render.output;
  EXPECT_TRUE(std::filesystem::exists(path("out") / "frame_0005.png"));
}

}  // namespace
}  // namespace dinam
