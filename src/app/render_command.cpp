// dinam render: a scene (or a motion cache) drawn frame by frame into PNG files and a movie.
#include "app/command_line.hpp"
#include "app/commands.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <system_error>

#include "app/command_support.hpp"
#include "app/render_input.hpp"
#include "cache/motion_cache.hpp"
#include "core/counted.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/thread_team.hpp"
#include "dynamics/stability.hpp"
#include "estimate/memory_estimate.hpp"
#include "estimate/run_estimate.hpp"
#include "io/movie_encoder.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "run/energy_csv.hpp"
#include "run/frame_folder.hpp"
#include "run/frame_range.hpp"
#include "run/frame_source.hpp"
#include "run/frame_writer.hpp"
#include "run/progress.hpp"
#include "scene/scene_description.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_drawing.hpp"
#include "visual/shot.hpp"

namespace dinam {

int run_render(const RenderOptions& options) {
  if (options.preview) {
    return run_preview(options);
  }
  const RenderInput input = read_render_input(options);
  const SceneDescription& scene = input.scene;
  const FrameRange& range = input.range;
  const std::optional<MotionCache>& cache = input.cache;
  const Model& model = input.model;
  const std::optional<TimeStep>& timestep = input.timestep;
  const std::filesystem::path folder = options.output.value_or(scene.output);
  check_output_place(folder, OutputPlace::kInside, options.output ? "-o" : "the output folder");
  create_folder(folder);
  // Every name the run will write, refused now if one is a link or a special file, rather than
  // after minutes of simulation (core/output_file.hpp checks each again as it is written).
  const std::vector<int>& chosen = input.frames;
  for (const int frame : chosen) {
    check_output_name(folder / frame_file_name(frame, scene.frame_count()));
  }
  // A movie is of frames one after another: none where --frames leaves gaps.
  const bool one_run = static_cast<int>(chosen.size()) == range.count();
  const MovieFormat movie_format = one_run ? scene.movie : MovieFormat::kNone;
  check_output_name(folder / kFrameFolderInfoName);
  if (options.energy_csv) {
    check_output_name(folder / "energy.csv");
  }
  if (movie_format != MovieFormat::kNone) {
    check_output_name(folder / movie_file_name(scene.name, scene.movie, range.first, range.last,
                                               scene.frame_count()));
  }
  const auto start = Clock::now();
  const StopOnSignals stop_on_signals;

  // 1. The motion.
  std::optional<EnergyCsv> energy_csv;
  if (options.energy_csv) {
    energy_csv.emplace(folder / "energy.csv");
  }
  const SimulatedFrames frames =
      render_motion(input, options.quiet, energy_csv ? &*energy_csv : nullptr);
  if (energy_csv) {
    energy_csv->close();
  }

  // 2. Draw the frames; a thread of their own writes them (PNG) and feeds them to ffmpeg, which
  //    encodes the movie meanwhile.
  const Shot shot = make_shot(scene, model, frames, input.textures);
  const DrawList& draw_list = shot.draw_list;
  const FrameCameras& cameras = shot.cameras;
  OsmesaRenderer renderer(render_settings(scene));
  int exit_code = kExitOk;
  std::string movie_note;
  std::unique_ptr<MovieEncoder> movie;
  std::filesystem::path movie_path;
  if (movie_format != MovieFormat::kNone) {
    const bool gif = scene.movie == MovieFormat::kGif;
    movie_path = folder / movie_file_name(scene.name, scene.movie, range.first, range.last,
                                          scene.frame_count());
    movie = MovieEncoder::start(
        {scene.image_width, scene.image_height, scene.fps, movie_path, gif, stop_if_asked});
    if (!movie) {
      fmt::print(stderr,
                 "dinam: ffmpeg was not found, so no movie will be made; the frames will be in "
                 "{}. Install it with: sudo apt-get install ffmpeg\n",
                 folder.string());
      exit_code = kExitFailure;
    }
  }
  if (!one_run) {
    movie_note = ", no movie (the frames chosen are not one run)";
  }
  const int frame_count = static_cast<int>(chosen.size());
  Progress progress(frame_count, !options.quiet, "draw");
  const auto draw_start = Clock::now();
  {
    FrameWriter writer(folder, frame_number_digits(scene.frame_count()), movie.get());
    try {
      int drawn = 0;
      // Each run of consecutive frames in one call: a frame's drawing may follow the one before.
      for (std::size_t k = 0; k < chosen.size();) {
        std::size_t end = k + 1;
        while (end < chosen.size() && chosen[end] == chosen[end - 1] + 1) {
          ++end;
        }
        draw_frames(renderer, draw_list, frames, cameras, chosen[k], chosen[end - 1],
                    [&](int frame, const Image& image) {
                      stop_if_asked();
                      writer.write(frame, image);
                      progress.update(++drawn, fmt::format("draw and write {:.1f} s",
                                                           seconds_since(draw_start)));
                    });
        k = end;
      }
      writer.finish();
    } catch (const Interrupted& e) {
      // The frames drawn so far are written whole; ffmpeg is stopped and its partial movie
      // removed when `movie` goes.
      writer.finish();
      progress.finish();
      throw Interrupted(e.signal(),
                        fmt::format("{} of the {} frames were written to {} and are kept; no "
                                    "movie was made",
                                    writer.frames_written(), frame_count, folder.string()));
    } catch (const RuntimeError& e) {
      // A frame that could not be written (a full disk), a run that diverged, an ffmpeg that
      // stalled: say what is left, as for a stop.
      progress.finish();
      const bool write_failed = dynamic_cast<const WriteError*>(&e) != nullptr;
      throw RuntimeError(fmt::format(
          "{}; {} of the {} frames were written to {} and are kept, no movie was made{}", e.what(),
          writer.frames_written(), frame_count, folder.string(),
          write_failed ? ". Free some space there or render to another folder (-o)" : ""));
    }
  }
  progress.finish();
  const FrameFolderInfo info{scene.name,        scene.fps,          scene.frame_count(),
                             scene.image_width, scene.image_height, input.scene_movie};
  write_frame_folder_info(folder, info);
  // Frame files that belong to no frame of this movie (past its last frame, or numbered with other
  // digits) are an earlier, longer render's: `dinam movie` would refuse the folder for them.
  if (const std::vector<std::string> stale = take_inventory(folder, info).extra; !stale.empty()) {
    for (const std::string& name : stale) {
      std::error_code ec;
      std::filesystem::remove(folder / name, ec);
    }
    if (!options.quiet) {
      fmt::print("dinam: removed {} frame{} left from an earlier, longer render ({} … {})\n",
                 stale.size(), stale.size() == 1 ? "" : "s", stale.front(), stale.back());
    }
  }
  const double draw_seconds = seconds_since(draw_start);

  // 3. The movie: ffmpeg finishes what it has been encoding all along.
  if (movie) {
    movie->finish();
    movie_note = fmt::format(", movie {}", movie_path.string());
  }
  if (!options.quiet) {
    if (const std::string settled = settle_summary(frames.settled, timestep ? timestep->dt : 0.0);
        !settled.empty()) {
      fmt::print("dinam: {}\n", settled);
    }
    fmt::print("dinam: {} in {}{} ({:.1f} s: {} {:.2f} s, draw and write {:.2f} s)\n",
               counted(frame_count, "frame"), folder.string(), movie_note, seconds_since(start),
               cache ? "read the cache" : "simulate", frames.seconds, draw_seconds);
  }
  return exit_code;
}

Command add_render_command(CLI::App& app, std::optional<int>& threads) {
  struct Parsed {
    RenderOptions options;
    bool no_video = false;  // applied after the parse, so that it wins over --movie
  };
  auto parsed = std::make_shared<Parsed>();
  CLI::App* render_command =
      app.add_subcommand("render", "Simulate a scene and write its frames (PNG) and movie (mp4)");
  render_command->add_option("scene", parsed->options.scene, "Scene file (YAML)")->required();
  add_optional_option(*render_command, "-o,--output", parsed->options.output,
                      "Output folder (default: the scene's 'output', else out/<name>)");
  render_command->add_option("--frames", parsed->options.frames,
                             "Frames to write: A, A-B or a list, 1,5,10-20 (1-based, inclusive; "
                             "'middle' and 'last' too); each is the frame of the whole movie (the "
                             "whole motion is simulated, or read with --cache); a list with gaps "
                             "makes no movie");
  render_command->add_option("--size", parsed->options.size, "Image size WxH, e.g. 640x360");
  render_command->add_option("--movie", parsed->options.movie,
                             "Movie format: mp4 (H.264), gif, or none (default: the scene's "
                             "'movie', else mp4)");
  render_command->add_flag("--no-video", parsed->no_video,
                           "Write the PNG frames only (--movie none)");
  render_command->add_flag("-q,--quiet", parsed->options.quiet, "Print nothing but errors");
  render_command->add_flag("--energy", parsed->options.energy_csv,
                           "Also write DIR/energy.csv: kinetic, elastic, gravitational and contact "
                           "energy, and what damping, plasticity, friction, wind and fields did, "
                           "one row per frame");
  add_optional_option(*render_command, "--cache", parsed->options.cache,
                      "Draw from this motion cache (made by 'dinam simulate') instead of "
                      "simulating; refused when the scene's motion has changed since");
  render_command->add_flag(
      "--preview", parsed->options.preview,
      "A quick look: draft quality, 320 pixels wide, about 30 frames spread over the motion, as "
      "DIR/NAME_preview.gif and a contact sheet DIR/NAME_preview.png");
  render_command->add_flag("--force", parsed->options.force,
                           "Run even when the memory the run needs (see 'dinam info') passes "
                           "what the machine has available, or its run time an hour");
  add_threads_option(*render_command, threads);

  return {render_command, [parsed](const ThreadChoice&) {
            RenderOptions options = parsed->options;
            if (parsed->no_video) {
              options.movie = "none";
            }
            return run_render(options);
          }};
}

}  // namespace dinam
