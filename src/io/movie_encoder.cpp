#include "io/movie_encoder.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"

extern char** environ;

namespace dinam {

std::vector<std::string> ffmpeg_arguments(const MovieRequest& request,
                                          const std::filesystem::path& partial_output) {
  std::vector<std::string> arguments = {"ffmpeg",
                                        "-nostdin",
                                        "-y",
                                        "-loglevel",
                                        "error",
                                        "-framerate",
                                        fmt::format("{}", request.fps),
                                        "-start_number",
                                        std::to_string(request.first_frame_number),
                                        "-i",
                                        request.frame_pattern.string(),
                                        "-frames:v",
                                        std::to_string(request.frame_count)};
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

MovieOutcome encode_movie(const MovieRequest& request) {
  std::filesystem::path partial = request.output;
  partial += ".part";
  std::filesystem::path log = request.output;
  log += ".ffmpeg-log";
  const std::vector<std::string> arguments = ffmpeg_arguments(request, partial);
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (const std::string& argument : arguments) {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);

  // ffmpeg's messages go to a log file so that a failure can quote them.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  std::error_code ec;
  if (spawn_error == ENOENT) {
    std::filesystem::remove(log, ec);
    return MovieOutcome::kFfmpegMissing;
  }
  if (spawn_error != 0) {
    std::filesystem::remove(log, ec);
    throw RuntimeError(fmt::format("cannot start ffmpeg: {}", std::strerror(spawn_error)));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::stringstream messages;
  messages << std::ifstream(log).rdbuf();
  std::filesystem::remove(log, ec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(partial, ec);
    throw RuntimeError(fmt::format("ffmpeg failed making {} (exit status {}):\n{}",
                                   request.output.string(),
                                   WIFEXITED(status) ? WEXITSTATUS(status) : -1, messages.str()));
  }
  std::filesystem::rename(partial, request.output, ec);
  if (ec) {
    throw RuntimeError(fmt::format("cannot rename {} to {}: {}", partial.string(),
                                   request.output.string(), ec.message()));
  }
  return MovieOutcome::kWritten;
}

}  // namespace dinam
