#include "run/frame_range.hpp"

#include <charconv>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace dinam {
namespace {

bool parse_int(std::string_view text, int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

FrameRange parse_frame_range(const std::string& text, int frame_count) {
  FrameRange range;
  const std::size_t dash = text.find('-');
  const bool ok = dash == std::string::npos
                      ? parse_int(text, range.first) && parse_int(text, range.last)
                      : parse_int(std::string_view(text).substr(0, dash), range.first) &&
                            parse_int(std::string_view(text).substr(dash + 1), range.last);
  if (!ok) {
    throw_user_error({},
                     "--frames takes frames and ranges, such as 12, 30-40 or 1,5,10-20 (1-based "
                     "frame numbers), got '{}'",
                     text);
  }
  if (range.first > range.last) {
    throw_user_error({}, "--frames {}: the first frame comes after the last; write {}-{}", text,
                     range.last, range.first);
  }
  if (range.first < 1 || range.last > frame_count) {
    throw_user_error({}, "--frames {} is outside the scene's frames 1-{}", text, frame_count);
  }
  return range;
}

std::vector<int> parse_frame_list(const std::string& text, int frame_count) {
  std::set<int> frames;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item == "middle") {
      item = std::to_string((frame_count + 1) / 2);
    } else if (item == "last") {
      item = std::to_string(frame_count);
    }
    const FrameRange range = parse_frame_range(item, frame_count);
    for (int f = range.first; f <= range.last; ++f) {
      frames.insert(f);
    }
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
  return {frames.begin(), frames.end()};
}

void parse_image_size(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  int w = 0;
  int h = 0;
  if (x == std::string::npos || !parse_int(std::string_view(text).substr(0, x), w) ||
      !parse_int(std::string_view(text).substr(x + 1), h)) {
    throw_user_error({}, "--size takes WIDTHxHEIGHT in pixels, e.g. 1280x720; got '{}'", text);
  }
  if (w < 16 || w > 8192 || h < 16 || h > 8192) {
    throw_user_error({}, "--size {}: width and height must be between 16 and 8192", text);
  }
  width = w;
  height = h;
}

}  // namespace dinam
