#pragma once
// The movie is made by the ffmpeg command-line program, run as a child process with an argument
// vector (no shell, so no quoting problems with odd folder names). It runs beside the renderer:
// each frame goes to it through a pipe as raw RGBA as soon as it is drawn, so encoding overlaps
// drawing instead of following it.
//
// A scene file is input from anyone, so ffmpeg gets files and nothing else: the movie's path is
// absolute and written "file:/…" (no name can read as an option, a protocol such as tcp:// or
// concat:, or a device), the input is restricted to the pipe (-protocol_whitelist), and ffmpeg
// writes into a new file of our own (created with O_EXCL, core/output_file.hpp), renamed to the
// movie's name when it succeeds; a movie name that is a link or a special file is refused before
// ffmpeg starts. An ffmpeg that stops reading and stops working (no byte taken from the pipe and
// no CPU time used for `stall_seconds`) is stopped with a message, never waited for for ever.
#include <sys/types.h>

#include <filesystem>
#include <functional>
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
  // Called about once a second while ffmpeg is being waited for; it may throw to give up (the
  // render's signal check).
  std::function<void()> while_waiting = {};
};

// The ffmpeg program: DINAM_FFMPEG when set (a path or a name on PATH), else "ffmpeg".
std::string ffmpeg_program();

// How long ffmpeg may take no input and use no CPU before it is stopped: DINAM_FFMPEG_TIMEOUT
// seconds when set, else 60. Throws UserError for a value that is not a positive number.
double ffmpeg_stall_seconds();

class MovieEncoder {
 public:
  // Starts ffmpeg. Returns null when no ffmpeg program is on PATH (the caller says so and keeps
  // the frames); throws UserError when the movie's name is a link or a special file, and
  // RuntimeError when ffmpeg cannot be started for another reason.
  static std::unique_ptr<MovieEncoder> start(const MovieRequest& request);

  // Sends one frame (of the request's size). If ffmpeg has stopped, the frame is dropped; finish()
  // then reports why. Throws RuntimeError when ffmpeg has stalled (and stops it).
  void add_frame(const Image& image);

  // Ends the input, waits for ffmpeg and renames the movie into place. Throws RuntimeError with
  // ffmpeg's own message when it failed (and leaves no movie).
  void finish();

  // Unfinished (an error elsewhere), stops ffmpeg and removes the partial movie.
  ~MovieEncoder();
  MovieEncoder(const MovieEncoder&) = delete;
  MovieEncoder& operator=(const MovieEncoder&) = delete;

 private:
  MovieEncoder(MovieRequest request, std::filesystem::path partial, int log, pid_t pid, int pipe);
  void stop_unfinished();
  // Waits for the pipe to take bytes, or for ffmpeg to exit when `for_exit`; throws RuntimeError
  // when ffmpeg neither takes input nor uses CPU for stall_seconds_. Returns ffmpeg's status
  // when it has exited (for_exit), else 0.
  int wait_for_progress(bool for_exit);
  std::string log_text() const;

  MovieRequest request_;
  std::filesystem::path partial_;  // ffmpeg's output, ours, renamed to request_.output at the end
  int log_ = -1;                   // ffmpeg's standard error, a file removed as soon as made
  pid_t pid_ = -1;
  int pipe_ = -1;  // ffmpeg's standard input; -1 once closed
  double stall_seconds_ = 60.0;
};

// The argument vector MovieEncoder runs, exposed for tests. `partial_output` must be absolute.
std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output);

}  // namespace dinam
