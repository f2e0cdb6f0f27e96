#pragma once
// Small things every command needs: wall time, output folders, the movie format option, and
// stopping cleanly on SIGINT or SIGTERM.
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

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

// Thrown between frames after SIGINT or SIGTERM, so that the command unwinds and its destructors
// remove what it had not finished (a temporary cache folder, a partial movie, ffmpeg itself).
class Interrupted : public std::runtime_error {
 public:
  // `outcome` says what was kept and what was not made; a generic sentence without it.
  explicit Interrupted(int signal, const std::string& outcome = "");
  int signal() const { return signal_; }

 private:
  int signal_;
};

// While one exists, SIGINT and SIGTERM only ask the command to stop (the first one; a second
// ends the program at once, as without it).
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
};

// The signal that asked to stop, or 0.
int stop_signal();

// Throws Interrupted when a signal has asked to stop.
void stop_if_asked();

}  // namespace dinam
