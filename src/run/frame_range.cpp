#include "run/frame_range.hpp"

#include <charconv>

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
    throw_user_error({}, "--frames takes A-B or A (1-based frame numbers), got '{}'", text);
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
