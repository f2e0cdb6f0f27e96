// dinam: scene file → simulated motion → rendered frames → movie.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/cpu_share.hpp"
#include "core/error.hpp"
#include "core/thread_team.hpp"
#include "core/version.hpp"

namespace {

// A file whose name starts with a dash reads as an option; when the command line did not parse,
// say so for each argument that is such a file, and how to name it.
void explain_dash_led_files(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    std::error_code ec;
    if (argument.size() > 1 && argument[0] == '-' && argument != "--" &&
        std::filesystem::exists(argument, ec)) {
      fmt::print(stderr,
                 "dinam: '{0}' is a file, but a name that starts with '-' reads as an option; "
                 "write it as ./{0}\n",
                 argument);
    }
  }
}

int run(int argc, char** argv) {
  using namespace dinam;
  CLI::App app{
      "dinam: physically simulated animation of flexible structures (rigid bar spring "
      "model, explicit central differences, off-screen OpenGL)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dinam ") + kVersion);
  // The commands that simulate take the thread count; without it, DINAM_THREADS, else the CPUs
  // the process is given (core/cpu_share.hpp).
  std::optional<int> threads;
  auto add_threads_option = [&threads](CLI::App* command) {
    command
        ->add_option("--threads", threads,
                     "Threads to simulate on (default: DINAM_THREADS, else the CPUs this process "
                     "is given: its affinity mask, cgroup quota and SLURM_CPUS_PER_TASK; "
                     "'dinam info' says which); the motion is the same for any count")
        ->check(CLI::Range(1, 4096));
  };

  RenderOptions render;
  std::string output;
  CLI::App* render_command =
      app.add_subcommand("render", "Simulate a scene and write its frames (PNG) and movie (mp4)");
  render_command->add_option("scene", render.scene, "Scene file (YAML)")->required();
  render_command->add_option("-o,--output", output,
                             "Output folder (default: the scene's 'output', else out/<name>)");
  render_command->add_option("--frames", render.frames,
                             "Frames to write, A-B (1-based, inclusive); each is the frame of the "
                             "whole movie (the whole motion is simulated, or read with --cache)");
  render_command->add_option("--size", render.size, "Image size WxH, e.g. 640x360");
  bool no_video = false;
  render_command->add_option("--movie", render.movie,
                             "Movie format: mp4 (H.264), gif, or none (default: the scene's "
                             "'movie', else mp4)");
  render_command->add_flag("--no-video", no_video, "Write the PNG frames only (--movie none)");
  render_command->add_flag("-q,--quiet", render.quiet, "Print nothing but errors");
  render_command->add_flag("--energy", render.energy_csv,
                           "Also write DIR/energy.csv: kinetic, elastic, gravitational and contact "
                           "energy, and what damping, plasticity, friction, wind and fields did, "
                           "one row per frame");
  std::string render_cache;
  render_command->add_option("--cache", render_cache,
                             "Draw from this motion cache (made by 'dinam simulate') instead of "
                             "simulating; refused when the scene's motion has changed since");
  render_command->add_flag(
      "--preview", render.preview,
      "A quick look: draft quality, 320 pixels wide, about 30 frames spread over the motion, as "
      "DIR/NAME_preview.gif and a contact sheet DIR/NAME_preview.png");
  render_command->add_flag("--force", render.force,
                           "Run even when the memory the run needs (see 'dinam info') passes "
                           "what the machine has available, or its run time an hour");
  add_threads_option(render_command);

  SimulateOptions simulate;
  std::string simulate_output;
  CLI::App* simulate_command = app.add_subcommand(
      "simulate",
      "Simulate a scene once into a motion cache: per object a rest mesh (OBJ) and point caches "
      "(PC2, MDD) that 'render --cache' draws from and Blender, Houdini and 3ds Max open, plus "
      "manifest.json");
  simulate_command->add_option("scene", simulate.scene, "Scene file (YAML)")->required();
  simulate_command->add_option("-o,--output", simulate_output,
                               "Cache folder (default: the scene's 'output'/cache); an older "
                               "cache there is replaced when the new one is complete");
  simulate_command
      ->add_option(
          "--format", simulate.formats,
          "What the cache holds beside the rest meshes: a list of pc2, mdd (point caches) and "
          "usd (a USD stage of every object)")
      ->default_val(simulate.formats);
  simulate_command->add_flag("-q,--quiet", simulate.quiet, "Print nothing but errors");
  simulate_command->add_flag("--energy", simulate.energy,
                             "Also record the energy report, one row per frame, in "
                             "manifest.json and energy.csv");
  simulate_command->add_flag("--force", simulate.force,
                             "Run even when the memory the run needs (see 'dinam info') passes "
                             "what the machine has available, or its run time an hour");
  add_threads_option(simulate_command);

  MovieOptions movie;
  CLI::App* movie_command = app.add_subcommand(
      "movie",
      "Assemble the frames in a folder (drawn by 'dinam render', at once or in chunks) into "
      "the movie; missing or extra frames are named and nothing is made");
  movie_command->add_option("folder", movie.folder, "Folder of frame_NNNN.png and frames.json")
      ->required();
  std::string movie_format;
  movie_command->add_option("--movie", movie_format,
                            "mp4 or gif (default: the scene's 'movie', else mp4)");
  movie_command->add_flag("-q,--quiet", movie.quiet, "Print nothing but errors");

  SnapshotOptions snapshot;
  std::string snapshot_output;
  CLI::App* snapshot_command = app.add_subcommand(
      "snapshot",
      "Render chosen frames small and compare each with a golden PNG under a tolerance; exit 1 "
      "on any difference, writing actual, expected and difference images");
  snapshot_command->add_option("scene", snapshot.scene, "Scene file (YAML)")->required();
  snapshot_command
      ->add_option("--golden", snapshot.golden, "Folder of golden images <name>_NNNN.png")
      ->required();
  snapshot_command->add_option("--frames", snapshot.frames,
                               "Frames to check, e.g. 1,60,120 or 1-3,9 (default: first, middle "
                               "and last)");
  snapshot_command->add_option("--size", snapshot.size, "Image size WxH")->default_val("320x180");
  snapshot_command->add_option("-o,--output", snapshot_output,
                               "Where differing frames' actual/expected/diff images go (default "
                               "out/snapshot/<name>)");
  snapshot_command->add_flag("--update", snapshot.update,
                             "Write the rendered frames as the new goldens instead of comparing");
  snapshot_command
      ->add_option("--threshold", snapshot.tolerance.threshold,
                   "A pixel differs when a channel differs by more than this (0-255)")
      ->default_val(snapshot.tolerance.threshold)
      ->check(CLI::Range(0, 255));
  snapshot_command
      ->add_option("--max-differing", snapshot.tolerance.max_differing_fraction,
                   "Largest fraction of differing pixels that still matches")
      ->default_val(snapshot.tolerance.max_differing_fraction)
      ->check(CLI::Range(0.0, 1.0));
  snapshot_command
      ->add_option("--max-mean-error", snapshot.tolerance.max_mean_error,
                   "Largest mean channel error (0-255) that still matches")
      ->default_val(snapshot.tolerance.max_mean_error)
      ->check(CLI::Range(0.0, 255.0));
  snapshot_command->add_flag("-q,--quiet", snapshot.quiet, "Print only differences and errors");
  add_threads_option(snapshot_command);

  ModesOptions modes;
  std::string modes_output;
  CLI::App* modes_command = app.add_subcommand(
      "modes",
      "Print the lowest natural frequencies and mode shapes of a scene's structure at rest under "
      "gravity, and write them as a motion cache (one object per mode)");
  modes_command->add_option("scene", modes.scene, "Scene file (YAML)")->required();
  modes_command->add_option("--count", modes.count, "How many of the lowest modes")
      ->default_val(modes.count)
      ->check(CLI::Range(1, 1000));
  modes_command->add_option("-o,--output", modes_output,
                            "Cache folder to write (default: the scene's output folder/modes)");
  modes_command->add_flag("-q,--quiet", modes.quiet, "Print nothing but errors");
  add_threads_option(modes_command);

  ViewOptions view;
  std::string view_output;
  CLI::App* view_command = app.add_subcommand(
      "view",
      "Write a motion cache as one web page that plays it (orbit, timeline, play/pause): open it "
      "in any browser, offline");
  view_command->add_option("cache", view.cache, "Motion cache folder (dinam simulate)")->required();
  view_command->add_option("-o,--output", view_output,
                           "The page to write (default: the cache folder's name with .html)");
  view_command->add_option("--every", view.every, "Keep every Nth frame (a smaller page)")
      ->default_val(view.every)
      ->check(CLI::Range(1, 100000));
  view_command->add_flag("-q,--quiet", view.quiet, "Print nothing but errors");

  std::filesystem::path info_scene;
  CLI::App* info_command =
      app.add_subcommand("info",
                         "Print the model summary of a scene: nodes, bars, springs, "
                         "mass, time step");
  info_command->add_option("scene", info_scene, "Scene file (YAML)")->required();
  bool info_json = false;
  info_command->add_flag("--json", info_json, "Print one JSON object, for scripts");
  bool info_energy = false;
  info_command->add_flag("--energy", info_energy,
                         "Also say what energy balance the time step gives (energy.csv's "
                         "total_J) and what step gives 0.1 %");
  add_threads_option(info_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    explain_dash_led_files(argc, argv);
    return kExitBadInput;
  }

  try {
    const ThreadChoice thread_choice = choose_threads(threads);
    set_thread_count(thread_choice.threads);
    // OSMesa's llvmpipe draws on as many threads as the machine has CPUs unless told otherwise:
    // the same share as the simulation's, unless the user has set it.
    setenv("LP_NUM_THREADS", std::to_string(thread_choice.threads).c_str(), 0);
    if (*render_command) {
      if (!output.empty()) {
        render.output = output;
      }
      if (no_video) {
        render.movie = "none";
      }
      if (!render_cache.empty()) {
        render.cache = render_cache;
      }
      return run_render(render);
    }
    if (*simulate_command) {
      if (!simulate_output.empty()) {
        simulate.output = simulate_output;
      }
      return run_simulate(simulate);
    }
    if (*movie_command) {
      if (!movie_format.empty()) {
        movie.movie = movie_format;
      }
      return run_movie(movie);
    }
    if (*modes_command) {
      if (!modes_output.empty()) {
        modes.output = modes_output;
      }
      return run_modes(modes);
    }
    if (*view_command) {
      if (!view_output.empty()) {
        view.output = view_output;
      }
      return run_view(view);
    }
    if (*snapshot_command) {
      if (!snapshot_output.empty()) {
        snapshot.output = snapshot_output;
      }
      return run_snapshot(snapshot);
    }
    return run_info(info_scene, info_json, thread_choice, info_energy);
  } catch (const Interrupted& e) {
    fmt::print(stderr, "dinam: {}\n", e.what());
    return 128 + e.signal();
  } catch (const UserError& e) {
    fmt::print(stderr, "{}: error: {}\n", e.loc().known() ? e.loc().to_string() : "dinam",
               e.message());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "dinam: error: {}\n", e.what());
    return dinam::kExitFailure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Nothing may escape: even a failure to print the message exits with the failure code.
  try {
    return run(argc, argv);
  } catch (...) {
    return dinam::kExitFailure;
  }
}
