#include "io/movie_encoder.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/thread_team.hpp"

extern char** environ;

namespace dinam {

namespace {

// User and system CPU time of a process, in clock ticks; -1 when it cannot be read.
long long cpu_ticks(pid_t pid) {
  std::ifstream stat_file(fmt::format("/proc/{}/stat", pid));
  std::string text((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
  // "pid (name) state ppid …": the name may hold spaces, so count from its closing parenthesis.
  const std::size_t name_end = text.rfind(')');
  if (name_end == std::string::npos) {
    return -1;
  }
  std::istringstream fields(text.substr(name_end + 1));
  std::string field;
  long long utime = 0;
  long long stime = 0;
  for (int f = 3; f <= 15 && fields >> field; ++f) {  // fields 14 and 15 are utime and stime
    if (f == 14) {
      utime = std::atoll(field.c_str());
    } else if (f == 15) {
      stime = std::atoll(field.c_str());
    }
  }
  return utime + stime;
}

void wait_for_exit(pid_t pid, int& status) {
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

std::string ffmpeg_program() {
  const char* program = std::getenv("DINAM_FFMPEG");
  return program != nullptr && *program != '\0' ? program : "ffmpeg";
}

double ffmpeg_stall_seconds() {
  const char* text = std::getenv("DINAM_FFMPEG_TIMEOUT");
  if (text == nullptr || *text == '\0') {
    return 60.0;
  }
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(seconds > 0.0) || !std::isfinite(seconds)) {
    throw_user_error({},
                     "DINAM_FFMPEG_TIMEOUT is '{}'; give the seconds ffmpeg may stall as a "
                     "positive number, or unset it for 60",
                     text);
  }
  return seconds;
}

std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output) {
  DINAM_CHECK(partial_output.is_absolute());
  // The input: raw RGBA frames, top row first, on standard input and nowhere else.
  std::vector<std::string> arguments = {ffmpeg_program(),
                                        "-nostdin",
                                        "-y",
                                        "-loglevel",
                                        "error",
                                        "-protocol_whitelist",
                                        "pipe",
                                        "-f",
                                        "rawvideo",
                                        "-pix_fmt",
                                        "rgba",
                                        "-video_size",
                                        fmt::format("{}x{}", request.width, request.height),
                                        "-framerate",
                                        fmt::format("{}", request.fps),
                                        "-i",
                                        "pipe:0"};
  if (request.gif) {
    // One palette from all frames, then an ordered (Bayer) dither: unlike error diffusion it
    // depends on nothing but the pixel, so the same frames always give the same file.
    const std::string palette_filter =
        "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=bayer:bayer_scale=3";
    arguments.insert(arguments.end(),
                     {"-filter_complex", palette_filter, "-loop", "0", "-f", "gif"});
  } else {
    // H.264 in yuv420p needs even dimensions; pad an odd one by a pixel. The frames are sRGB,
    // whose primaries are BT.709's: they are turned into YUV with BT.709's matrix in its limited
    // range (ffmpeg's default matrix is BT.601's) and the stream says so, so that players and
    // compositors turn them back with the same matrix rather than guess.
    arguments.insert(arguments.end(),
                     {"-vf",
                      "pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv",
                      "-c:v",
                      "libx264",
                      "-preset",
                      "veryfast",
                      "-crf",
                      "18",
                      "-pix_fmt",
                      "yuv420p",
                      "-colorspace",
                      "bt709",
                      "-color_primaries",
                      "bt709",
                      "-color_trc",
                      "bt709",
                      "-color_range",
                      "tv",
                      "-movflags",
                      "+faststart",
                      "-f",
                      "mp4"});
  }
  // ffmpeg would take every CPU of the machine; it gets the process's thread count, which
  // follows the process's share and the machine's load (core/thread_governor.hpp).
  arguments.insert(arguments.end(), {"-threads", std::to_string(thread_count())});
  // The output: a local file only (mp4's faststart reads it back, so "file" it is, not "pipe"),
  // named by an absolute path after "file:", which no name can turn into an option or a protocol.
  arguments.insert(arguments.end(),
                   {"-protocol_whitelist", "file", "file:" + partial_output.string()});
  return arguments;
}

std::unique_ptr<MovieEncoder> MovieEncoder::start(const MovieRequest& request) {
  check_output_name(request.output);
  const double stall_seconds = ffmpeg_stall_seconds();
  // A write to the pipe of an ffmpeg that has exited raises SIGPIPE, which would end dinam
  // without a word; ignored, the write fails instead and finish() quotes ffmpeg's message.
  std::signal(SIGPIPE, SIG_IGN);

  // ffmpeg writes into a new file of ours; its messages go to a file unlinked at once, read
  // through our descriptor when a failure quotes them.
  std::filesystem::path partial;
  std::filesystem::path stem = std::filesystem::absolute(request.output);
  stem += ".part";
  close(create_exclusive_file(stem, partial));
  std::filesystem::path log_name;
  std::filesystem::path log_stem = stem;
  log_stem += "-log";
  const int log = create_exclusive_file(log_stem, log_name);
  unlink(log_name.c_str());

  const std::vector<std::string> arguments = ffmpeg_arguments(request, partial);
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const std::string& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);

  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    const int error = errno;
    close(log);
    unlink(partial.c_str());
    throw RuntimeError(fmt::format("cannot make a pipe to ffmpeg: {}", std::strerror(error)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[0]);
  if (spawn_error != 0) {
    close(ends[1]);
    close(log);
    unlink(partial.c_str());
    if (spawn_error == ENOENT) {
      return nullptr;
    }
    throw RuntimeError(
        fmt::format("cannot start {}: {}", arguments.front(), std::strerror(spawn_error)));
  }
  // Our end does not block: a full pipe is waited on by poll, with ffmpeg's progress in view.
  fcntl(ends[1], F_SETFL, fcntl(ends[1], F_GETFL) | O_NONBLOCK);
  auto encoder = std::unique_ptr<MovieEncoder>(
      new MovieEncoder(request, std::move(partial), log, pid, ends[1]));
  encoder->stall_seconds_ = stall_seconds;
  return encoder;
}

MovieEncoder::MovieEncoder(MovieRequest request, std::filesystem::path partial, int log, pid_t pid,
                           int pipe)
    : request_(std::move(request)),
      partial_(std::move(partial)),
      log_(log),
      pid_(pid),
      pipe_(pipe) {}

int MovieEncoder::wait_for_progress(bool for_exit) {
  using Clock = std::chrono::steady_clock;
  auto last_progress = Clock::now();
  long long last_ticks = cpu_ticks(pid_);
  constexpr int kSliceMs = 100;
  for (int slice = 1;; ++slice) {
    if (for_exit) {
      int status = 0;
      const pid_t done = waitpid(pid_, &status, WNOHANG);
      if (done == pid_) {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(kSliceMs));
    } else {
      pollfd ready{pipe_, POLLOUT, 0};
      if (poll(&ready, 1, kSliceMs) > 0) {
        return 0;  // room in the pipe, or ffmpeg gone (the write says which)
      }
    }
    const long long ticks = cpu_ticks(pid_);
    if (ticks != last_ticks) {
      last_ticks = ticks;
      last_progress = Clock::now();
    }
    if (slice % 10 == 0 && request_.while_waiting) {
      request_.while_waiting();
    }
    const double stalled = std::chrono::duration<double>(Clock::now() - last_progress).count();
    if (stalled > stall_seconds_) {
      stop_unfinished();
      throw RuntimeError(fmt::format(
          "ffmpeg ({}) took no {} and used no CPU for {:.0f} s, so it was stopped and {} "
          "left unmade. Check that it is a working ffmpeg, or give a slow one more time with "
          "DINAM_FFMPEG_TIMEOUT (seconds)",
          ffmpeg_program(), for_exit ? "steps towards finishing" : "frame data", stalled,
          request_.output.string()));
    }
  }
}

void MovieEncoder::add_frame(const Image& image) {
  const std::uint8_t* data = image.rgba.data();
  std::size_t left = image.rgba.size();
  while (left > 0 && pipe_ >= 0) {
    const ssize_t written = write(pipe_, data, left);
    if (written < 0 && errno == EINTR) {
      continue;
    }
    if (written < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      wait_for_progress(false);
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

std::string MovieEncoder::log_text() const {
  std::string text;
  std::array<char, 4096> buffer{};
  off_t offset = 0;
  for (ssize_t n = 0; (n = pread(log_, buffer.data(), buffer.size(), offset)) > 0; offset += n) {
    text.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return text;
}

void MovieEncoder::finish() {
  if (pipe_ >= 0) {
    close(pipe_);
    pipe_ = -1;
  }
  const int status = wait_for_progress(true);
  const std::string messages = log_text();
  close(log_);
  log_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    unlink(partial_.c_str());
    throw RuntimeError(fmt::format("ffmpeg failed making {} (exit status {}):\n{}",
                                   request_.output.string(),
                                   WIFEXITED(status) ? WEXITSTATUS(status) : -1, messages));
  }
  try {
    check_output_name(request_.output);  // made a link while ffmpeg ran? refuse it still
  } catch (...) {
    unlink(partial_.c_str());
    throw;
  }
  if (std::rename(partial_.c_str(), request_.output.c_str()) != 0) {
    const int error = errno;
    unlink(partial_.c_str());
    throw RuntimeError(fmt::format("cannot rename {} to {}: {}", partial_.string(),
                                   request_.output.string(), std::strerror(error)));
  }
}

MovieEncoder::~MovieEncoder() {
  stop_unfinished();
  if (log_ >= 0) {
    close(log_);
  }
}

void MovieEncoder::stop_unfinished() {
  if (pid_ < 0) {
    return;
  }
  if (pipe_ >= 0) {
    close(pipe_);
    pipe_ = -1;
  }
  kill(pid_, SIGKILL);  // an ffmpeg that stalls may not heed SIGTERM; its output is dropped
  int status = 0;
  wait_for_exit(pid_, status);
  pid_ = -1;
  unlink(partial_.c_str());
}

}  // namespace dinam
