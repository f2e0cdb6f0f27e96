#pragma once
// A folder of drawn frames, frame_0001.png …, and frames.json beside them, which says what they
// are (the scene's name, fps, how many frames the movie has, their size). Every render writes it,
// so that `dinam movie DIR` can assemble frames drawn in separate chunks, on separate machines,
// and tell which are missing.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_description.hpp"

namespace dinam {

struct FrameFolderInfo {
  std::string name;  // the scene's name: the movie is DIR/<name>.mp4
  double fps = 24.0;
  int frame_count = 0;  // frames of the whole movie, 1 … frame_count
  int width = 0;        // pixels, of every frame
  int height = 0;
  MovieFormat movie = MovieFormat::kMp4;  // the scene's choice
};

// Frame files are numbered from 1 with at least four digits: frame_0001.png.
int frame_number_digits(int frame_count);
std::string frame_file_name(int frame, int frame_count);

inline constexpr const char* kFrameFolderInfoName = "frames.json";

// Writes DIR/frames.json under a temporary name, then renames it, so that chunks rendered at once
// into one folder each leave a whole file. Throws RuntimeError when it cannot.
void write_frame_folder_info(const std::filesystem::path& folder, const FrameFolderInfo& info);

// Throws UserError naming DIR/frames.json when it is missing or malformed.
FrameFolderInfo read_frame_folder_info(const std::filesystem::path& folder);

// Which frames of the movie are missing from the folder, and which frame files in it belong to
// no frame of the movie (beyond its last frame, or numbered with other digits).
struct FrameInventory {
  std::vector<int> missing;
  std::vector<std::string> extra;  // file names
};
FrameInventory take_inventory(const std::filesystem::path& folder, const FrameFolderInfo& info);

// "3, 41-80, 97": sorted numbers with runs joined.
std::string number_ranges(const std::vector<int>& numbers);

}  // namespace dinam
