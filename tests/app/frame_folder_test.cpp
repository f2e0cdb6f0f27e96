// A folder of frames: which are missing and which do not belong, named by number.
#include "run/frame_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.hpp"

namespace dinam {
namespace {

TEST(FrameFolder, NumberRangesJoinRuns) {
  EXPECT_EQ(number_ranges({}), "");
  EXPECT_EQ(number_ranges({7}), "7");
  EXPECT_EQ(number_ranges({3, 41, 42, 43, 97}), "3, 41-43, 97");
}

TEST(FrameFolder, InventoryNamesMissingAndForeignFrames) {
  const test::TemporaryFolder folder("frames");
  const FrameFolderInfo info{"flag", 20.0, 12, 64, 48, MovieFormat::kMp4};
  write_frame_folder_info(folder.path(), info);
  for (const int frame : {1, 2, 3, 5, 9, 10, 11, 12}) {
    std::ofstream(folder.path() / frame_file_name(frame, info.frame_count)) << "png";
  }
  for (const char* name : {"frame_0013.png", "frame_07.png", "frame_0000.png", "notes.txt"}) {
    std::ofstream(folder.path() / name) << "x";
  }
  const FrameInventory inventory = take_inventory(folder.path(), info);
  EXPECT_EQ(inventory.missing, (std::vector<int>{4, 6, 7, 8}));
  EXPECT_EQ(inventory.extra,
            (std::vector<std::string>{"frame_0000.png", "frame_0013.png", "frame_07.png"}));

  const FrameFolderInfo read = read_frame_folder_info(folder.path());
  EXPECT_EQ(read.name, "flag");
  EXPECT_EQ(read.frame_count, 12);
  EXPECT_EQ(read.width, 64);
  EXPECT_EQ(read.movie, MovieFormat::kMp4);
  EXPECT_EQ(frame_file_name(7, 12), "frame_0007.png");
  EXPECT_EQ(frame_file_name(7, 12000), "frame_00007.png");
}

// A shorter render into the folder of a longer one: the frames past its end are the longer
// render's, removed and said so, and `dinam movie` then takes the folder.
TEST(FrameFolder, AShorterRenderRemovesTheFramesLeftPastItsEnd) {
  const test::TemporaryFolder folder("shorter");
  const std::filesystem::path scene = folder.path() / "short.yaml";
  std::ofstream(scene) << R"(version: 1
name: short
duration: 0.2
fps: 20
image: {width: 64, height: 48, quality: draft}
movie: none
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
    pinned: {indices: [0]}
)";
  const std::filesystem::path out = folder.path() / "out";
  std::filesystem::create_directories(out);
  for (int frame = 1; frame <= 8; ++frame) {  // a longer render's, 8 frames
    std::ofstream(out / frame_file_name(frame, 8)) << "png";
  }
  const test::CommandResult run = test::run_dinam({"render", scene.string(), "-o", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("removed 4 frames left from an earlier, longer render "
                            "(frame_0005.png … frame_0008.png)"),
            std::string::npos)
      << run.output;
  for (int frame = 1; frame <= 8; ++frame) {
    EXPECT_EQ(std::filesystem::exists(out / frame_file_name(frame, 8)), frame <= 4) << frame;
  }
  const test::CommandResult movie = test::run_dinam({"movie", out.string()});
  EXPECT_EQ(movie.exit_code, 0) << movie.output;
}

}  // namespace
}  // namespace dinam
