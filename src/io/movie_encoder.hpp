#pragma once
// The movie is made by the ffmpeg command-line program, run as a child process with an argument
// vector (no shell, so no quoting problems with odd folder names). It writes "<movie>.part" and
// the file is renamed when ffmpeg succeeds.
#include <filesystem>
#include <string>
#include <vector>

namespace dinam {

struct MovieRequest {
  std::filesystem::path frame_pattern;  // printf-style, e.g. DIR/frame_%04d.png
  int first_frame_number = 1;           // the number in the first file name
  int frame_count = 0;
  double fps = 24.0;
  std::filesystem::path output;  // DIR/name.mp4 (H.264, yuv420p, even dimensions) or name.gif
  bool gif = false;  // an animated GIF with one palette for the whole movie, Bayer-dithered
};

enum class MovieOutcome { kWritten, kFfmpegMissing };

// Runs ffmpeg. Returns kFfmpegMissing when no ffmpeg program is on PATH (the frames stay);
// throws RuntimeError with ffmpeg's own message when it runs and fails.
MovieOutcome encode_movie(const MovieRequest& request);

// The argument vector encode_movie runs, exposed for tests.
std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output);

}  // namespace dinam
