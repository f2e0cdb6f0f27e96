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

}  // namespace
}  // namespace dinam
