#include "run/movie_format.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace dinam {

MovieFormat parse_movie_format(const std::string& text) {
  if (text == "mp4") {
    return MovieFormat::kMp4;
  }
  if (text == "gif") {
    return MovieFormat::kGif;
  }
  if (text == "none") {
    return MovieFormat::kNone;
  }
  throw_user_error({}, "--movie takes mp4, gif or none; got '{}'", text);
}

const char* movie_format_name(MovieFormat format) {
  switch (format) {
    case MovieFormat::kMp4:
      return "mp4";
    case MovieFormat::kGif:
      return "gif";
    case MovieFormat::kNone:
      return "none";
  }
  return "none";
}

std::string movie_file_name(const std::string& name, MovieFormat format) {
  return name + (format == MovieFormat::kGif ? ".gif" : ".mp4");
}

std::string movie_file_name(const std::string& name, MovieFormat format, int first, int last,
                            int frame_count) {
  if (first == 1 && last == frame_count) {
    return movie_file_name(name, format);
  }
  return movie_file_name(fmt::format("{}_frames_{}-{}", name, first, last), format);
}

}  // namespace dinam
