#pragma once
// Small things every command needs: wall time, output folders, the movie format option, and
// stopping cleanly on SIGINT or SIGTERM.
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/stop_request.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// The scene's model, its warnings (a mesh's degenerate faces, dropped) printed to stderr.
Model build_model_telling_warnings(const SceneDescription& scene);

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Creates a folder and its parents; throws RuntimeError naming it when that fails.
void create_folder(const std::filesystem::path& folder);

// "mp4", "gif" or "none" (the --movie option); throws UserError otherwise.
MovieFormat parse_movie_format(const std::string& text);
const char* movie_format_name(MovieFormat format);
// The movie's file name: NAME.mp4 or NAME.gif (not for kNone).
std::string movie_file_name(const std::string& name, MovieFormat format);
// The movie of frames first … last of frame_count: the whole movie's name when they are all of
// them, else NAME_frames_A-B, so that a part never stands under the whole movie's name.
std::string movie_file_name(const std::string& name, MovieFormat format, int first, int last,
                            int frame_count);

// While one exists, SIGINT and SIGTERM only ask the command to stop (core/stop_request.hpp;
// the first one; a second ends the program at once, as without it).
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
};

}  // namespace dinam
