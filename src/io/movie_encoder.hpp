#pragma once
// The movie is made by the ffmpeg command-line program, run as a child process with an argument
// vector (no shell, so no quoting problems with odd folder names). It runs beside the renderer:
// each frame goes to it through a pipe as raw RGBA as soon as it is drawn, so encoding overlaps
// drawing instead of following it. ffmpeg writes "<movie>.part", renamed when it succeeds.
#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/image.hpp"

namespace dinam {

struct MovieRequest {
  int width = 0;  // pixels, of every frame
  int height = 0;
  double fps = 24.0;
  std::filesystem::path output;  // DIR/name.mp4 (H.264, yuv420p, even dimensions) or name.gif
  bool gif = false;  // an animated GIF with one palette for the whole movie, Bayer-dithered
};

class MovieEncoder {
 public:
  // Starts ffmpeg. Returns null when no ffmpeg program is on PATH (the caller says so and keeps
  // the frames); throws RuntimeError when it cannot be started for another reason.
  static std::unique_ptr<MovieEncoder> start(const MovieRequest& request);

  // Sends one frame (of the request's size). If ffmpeg has stopped, the frame is dropped; finish()
  // then reports why.
  void add_frame(const Image& image);

  // Ends the input, waits for ffmpeg and renames the movie into place. Throws RuntimeError with
  // ffmpeg's own message when it failed (and leaves no movie).
  void finish();

  // Unfinished (an error elsewhere), stops ffmpeg and removes the partial movie.
  ~MovieEncoder();
  MovieEncoder(const MovieEncoder&) = delete;
  MovieEncoder& operator=(const MovieEncoder&) = delete;

 private:
  MovieEncoder(MovieRequest request, pid_t pid, int pipe);
  void stop_unfinished();

  MovieRequest request_;
  pid_t pid_ = -1;
  int pipe_ = -1;  // ffmpeg's standard input; -1 once closed
};

// The argument vector MovieEncoder runs, exposed for tests.
std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output);

}  // namespace dinam
