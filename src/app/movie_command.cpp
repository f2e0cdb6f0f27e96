// `dinam movie DIR`: frames already on disk, drawn at once or in chunks on several machines,
// become the movie, encoded exactly as `dinam render` encodes it.
#include <fmt/format.h>

#include <memory>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/counted.hpp"
#include "core/error.hpp"
#include "io/movie_encoder.hpp"
#include "io/png_file.hpp"
#include "run/frame_folder.hpp"
#include "run/progress.hpp"

namespace dinam {

int run_movie(const MovieOptions& options) {
  const FrameFolderInfo info = read_frame_folder_info(options.folder);
  MovieFormat format = options.movie ? parse_movie_format(*options.movie) : info.movie;
  if (format == MovieFormat::kNone) {
    if (options.movie) {
      throw_user_error({}, "--movie none makes no movie; give mp4 or gif");
    }
    format = MovieFormat::kMp4;  // the scene asked for none when it was drawn
  }
  const FrameInventory inventory = take_inventory(options.folder, info);
  if (!inventory.missing.empty() || !inventory.extra.empty()) {
    std::string message =
        fmt::format("{} does not hold exactly the {} frames of '{}':", options.folder.string(),
                    info.frame_count, info.name);
    if (!inventory.missing.empty()) {
      message += fmt::format("\n  missing frames: {} (render them with --frames)",
                             number_ranges(inventory.missing));
    }
    if (!inventory.extra.empty()) {
      constexpr std::size_t kShown = 8;
      std::string names;
      for (std::size_t i = 0; i < inventory.extra.size() && i < kShown; ++i) {
        names += (i == 0 ? "" : ", ") + inventory.extra[i];
      }
      if (inventory.extra.size() > kShown) {
        names += fmt::format(" and {} more", inventory.extra.size() - kShown);
      }
      message += fmt::format("\n  frames that are not the movie's (remove them): {}", names);
    }
    message += "\nno movie was made";
    throw UserError(FileLoc{options.folder.string()}, message);
  }

  const bool gif = format == MovieFormat::kGif;
  const std::filesystem::path movie_path = options.folder / movie_file_name(info.name, format);
  const auto start = Clock::now();
  const StopOnSignals stop_on_signals;
  std::unique_ptr<MovieEncoder> movie =
      MovieEncoder::start({info.width, info.height, info.fps, movie_path, gif, stop_if_asked});
  if (!movie) {
    throw RuntimeError(
        "ffmpeg was not found, so no movie can be made. Install it with: sudo "
        "apt-get install ffmpeg");
  }
  Progress progress(info.frame_count, !options.quiet, "encode");
  for (int frame = 1; frame <= info.frame_count; ++frame) {
    if (const int signal = stop_signal(); signal != 0) {
      throw Interrupted(signal, "no movie was made; the frames are as they were");
    }
    const std::filesystem::path path = options.folder / frame_file_name(frame, info.frame_count);
    const Image image = read_png(path);
    if (image.width != info.width || image.height != info.height) {
      throw UserError(FileLoc{path.string()},
                      fmt::format("this frame is {}×{}, the movie's frames {}×{}; render it again "
                                  "at the movie's size, or all frames at this one",
                                  image.width, image.height, info.width, info.height));
    }
    movie->add_frame(image);
    progress.update(frame, fmt::format("{:.1f} s", seconds_since(start)));
  }
  progress.finish();
  movie->finish();
  if (!options.quiet) {
    fmt::print("dinam: movie {} from {} ({:.1f} s)\n", movie_path.string(),
               counted(info.frame_count, "frame"), seconds_since(start));
  }
  return kExitOk;
}

Command add_movie_command(CLI::App& app) {
  auto options = std::make_shared<MovieOptions>();
  CLI::App* movie_command = app.add_subcommand(
      "movie",
      "Assemble the frames in a folder (drawn by 'dinam render', at once or in chunks) into "
      "the movie; missing or extra frames are named and nothing is made");
  movie_command->add_option("folder", options->folder, "Folder of frame_NNNN.png and frames.json")
      ->required();
  add_optional_option(*movie_command, "--movie", options->movie,
                      "mp4 or gif (default: the scene's 'movie', else mp4)");
  movie_command->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");

  return {movie_command, [options](const ThreadChoice&) { return run_movie(*options); }};
}

}  // namespace dinam
