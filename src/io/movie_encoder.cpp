#include "io/movie_encoder.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"

extern char** environ;

namespace dinam {

namespace {

std::filesystem::path with_suffix(std::filesystem::path path, const char* suffix) {
  path += suffix;
  return path;
}

std::filesystem::path partial_path(const MovieRequest& request) {
  return with_suffix(request.output, ".part");
}

std::filesystem::path log_path(const MovieRequest& request) {
  return with_suffix(request.output, ".ffmpeg-log");
}

}  // namespace

std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output) {
  // The input: raw RGBA frames, top row first, on standard input.
  std::vector<std::string> arguments = {
      "ffmpeg",      "-y",
      "-loglevel",   "error",
      "-f",          "rawvideo",
      "-pix_fmt",    "rgba",
      "-video_size", fmt::format("{}x{}", request.width, request.height),
      "-framerate",  fmt::format("{}", request.fps),
      "-i",          "pipe:0"};
  if (request.gif) {
    // One palette from all frames, then an ordered (Bayer) dither: unlike error diffusion it
    // depends on nothing but the pixel, so the same frames always give the same file.
    const std::string palette_filter =
        "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=3";
    arguments.insert(arguments.end(),
                     {"-filter_complex", palette_filter, "-loop", "0", "-f", "gif"});
  } else {
    // H.264 in yuv420p needs even dimensions; pad an odd one by a pixel.
    arguments.insert(arguments.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                                       "-preset", "veryfast", "-crf", "18", "-pix_fmt", "yuv420p",
                                       "-movflags", "+faststart", "-f", "mp4"});
  }
  arguments.push_back(partial_output.string());
  return arguments;
}

std::unique_ptr<MovieEncoder> MovieEncoder::start(const MovieRequest& request) {
  // A write to the pipe of an ffmpeg that has exited raises SIGPIPE, which would end dinam
  // without a word; ignored, the write fails instead and finish() quotes ffmpeg's message.
  std::signal(SIGPIPE, SIG_IGN);
  const std::vector<std::string> arguments = ffmpeg_arguments(request, partial_path(request));
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const std::string& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);

  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw RuntimeError(fmt::format("cannot make a pipe to ffmpeg: {}", std::strerror(errno)));
  }
  // ffmpeg reads the frames from the pipe; its messages go to a log file that a failure quotes.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log_path(request).c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[0]);
  std::error_code ec;
  if (spawn_error != 0) {
    close(ends[1]);
    std::filesystem::remove(log_path(request), ec);
    if (spawn_error == ENOENT) {
      return nullptr;
    }
    throw RuntimeError(fmt::format("cannot start ffmpeg: {}", std::strerror(spawn_error)));
  }
  return std::unique_ptr<MovieEncoder>(new MovieEncoder(request, pid, ends[1]));
}

MovieEncoder::MovieEncoder(MovieRequest request, pid_t pid, int pipe)
    : request_(std::move(request)), pid_(pid), pipe_(pipe) {}

void MovieEncoder::add_frame(const Image& image) {
  const std::uint8_t* data = image.rgba.data();
  std::size_t left = image.rgba.size();
  while (left > 0 && pipe_ >= 0) {
    const ssize_t written = write(pipe_, data, left);
    if (written < 0 && errno == EINTR) {
      continue;
    }
    if (written <= 0) {  // ffmpeg has stopped reading: stop sending, finish() says why
      close(pipe_);
      pipe_ = -1;
      return;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void MovieEncoder::finish() {
  if (pipe_ >= 0) {
    close(pipe_);
    pipe_ = -1;
  }
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::stringstream messages;
  messages << std::ifstream(log_path(request_)).rdbuf();
  std::error_code ec;
  std::filesystem::remove(log_path(request_), ec);
  const std::filesystem::path partial = partial_path(request_);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(partial, ec);
    throw RuntimeError(fmt::format("ffmpeg failed making {} (exit status {}):\n{}",
                                   request_.output.string(),
                                   WIFEXITED(status) ? WEXITSTATUS(status) : -1, messages.str()));
  }
  std::filesystem::rename(partial, request_.output, ec);
  if (ec) {
    throw RuntimeError(fmt::format("cannot rename {} to {}: {}", partial.string(),
                                   request_.output.string(), ec.message()));
  }
}

MovieEncoder::~MovieEncoder() {
  stop_unfinished();
}

void MovieEncoder::stop_unfinished() {
  if (pid_ < 0) {
    return;
  }
  if (pipe_ >= 0) {
    close(pipe_);
    pipe_ = -1;
  }
  kill(pid_, SIGTERM);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::error_code ec;
  std::filesystem::remove(partial_path(request_), ec);
  std::filesystem::remove(log_path(request_), ec);
}

}  // namespace dinam
