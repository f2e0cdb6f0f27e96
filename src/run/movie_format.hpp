#pragma once
// The movie's format (the scene's `movie`, the --movie option) and its file's name.
#include <string>

#include "scene/scene_description.hpp"

namespace dinam {

// "mp4", "gif" or "none" (the --movie option); throws UserError otherwise.
MovieFormat parse_movie_format(const std::string& text);
const char* movie_format_name(MovieFormat format);
// The movie's file name: NAME.mp4 or NAME.gif (not for kNone).
std::string movie_file_name(const std::string& name, MovieFormat format);
// The movie of frames first … last of frame_count: the whole movie's name when they are all of
// them, else NAME_frames_A-B, so that a part never stands under the whole movie's name.
std::string movie_file_name(const std::string& name, MovieFormat format, int first, int last,
                            int frame_count);

}  // namespace dinam
