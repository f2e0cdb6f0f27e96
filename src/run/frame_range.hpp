#pragma once
// `--frames`: frames and ranges (1,5,10-20), 1-based, inclusive, within the scene's frames.
#include <string>
#include <vector>

namespace dinam {

struct FrameRange {
  int first = 1;  // 1-based frame number
  int last = 1;   // inclusive
  int count() const { return last - first + 1; }
};

// Parses "A-B" or a single "A". Throws UserError (with no file location) when it is malformed or
// outside 1..frame_count.
FrameRange parse_frame_range(const std::string& text, int frame_count);

// "1,5-7,12" → {1, 5, 6, 7, 12}, ascending, each once, each within 1..frame_count; "middle" and
// "last" stand for those frames, so a list need not know the scene's length. Throws UserError as
// parse_frame_range does.
std::vector<int> parse_frame_list(const std::string& text, int frame_count);

// `--size WxH`, each between 16 and 8192. Throws UserError when malformed.
void parse_image_size(const std::string& text, int& width, int& height);

}  // namespace dinam
