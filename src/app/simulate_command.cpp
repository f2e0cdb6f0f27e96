// `dinam simulate`: the motion once, into a cache that `render --cache` draws from and that
// Blender, Houdini, Maya and 3ds Max open.
#include <fmt/format.h>

#include <fmt/ranges.h>
#include <memory>

#include <optional>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "cache/motion_cache_writer.hpp"
#include "core/counted.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/thread_governor.hpp"
#include "dynamics/stability.hpp"
#include "estimate/memory_estimate.hpp"
#include "estimate/run_estimate.hpp"
#include "model/model.hpp"
#include "run/energy_csv.hpp"
#include "run/frame_source.hpp"
#include "run/progress.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/torn_drawing.hpp"

namespace dinam {
namespace {

// A comma-separated list of "pc2", "mdd" and "usd" → the request's formats.
void parse_formats(const std::string& text, CacheRequest& request) {
  request.pc2 = false;
  request.mdd = false;
  request.usd = false;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item == "pc2") {
      request.pc2 = true;
    } else if (item == "mdd") {
      request.mdd = true;
    } else if (item == "usd") {
      request.usd = true;
    } else {
      throw_user_error({}, "--format takes a list of pc2, mdd and usd, such as pc2,usd; got '{}'",
                       text);
    }
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
}

// How the scene draws each object, for the manifest and the USD stage (the radii come at the end,
// from the whole run's motion; the colours from the model).
std::vector<ObjectLook> object_looks(const SceneDescription& scene) {
  std::vector<ObjectLook> looks;
  for (const ObjectDesc& object : scene.objects) {
    ObjectLook& look = looks.emplace_back();
    look.surface = object.style != DrawStyle::kWire;
    look.wires = object.style != DrawStyle::kSurface;
    look.texture = look.surface ? object.texture : std::filesystem::path();
    look.finish = object.finish;
    look.shading = object.shading;
    look.sharp_angle = object.sharp_angle;
  }
  return looks;
}

// The radius each object's wires are drawn with, for the whole run's motion (as render draws
// them).
std::vector<float> drawn_wire_radii(const Model& model, const std::vector<FrameBounds>& frames) {
  Bounds motion;
  Bounds subject;
  for (const FrameBounds& frame : frames) {
    motion.add(frame.min);
    motion.add(frame.max);
    subject.add(frame.subject_min);
    subject.add(frame.subject_max);
  }
  return drawn_wire_radii(model, drawn_bounds(motion, subject));
}

}  // namespace

int run_simulate(const SimulateOptions& options) {
  // Everything that can be wrong with the input is found before the first file is written.
  const SceneDescription scene = read_scene(options.scene);
  const Model model = build_model_telling_warnings(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  CacheRequest request;
  parse_formats(options.formats, request);
  request.looks = object_looks(scene);
  request.folder = options.output.value_or(scene.output / "cache");
  check_output_place(request.folder, OutputPlace::kBeside,
                     options.output ? "-o" : "the cache folder");
  request.fps = scene.fps;
  request.frame_count = scene.frame_count();
  // With motion blur in the scene, the instants its frames average go into the cache too, so
  // that frames drawn from it are those of a whole run.
  request.instant_offsets = shutter_offsets(scene.quality.motion_blur, timestep.steps_per_frame);
  request.shutter = scene.quality.motion_blur.shutter;
  request.steps_per_frame = timestep.steps_per_frame;
  // One frame's positions at a time: each goes to the files as soon as it is simulated.
  refuse_if_over_budget(options.scene, scene.duration_loc,
                        estimate_memory(scene, model, {2, options.energy, 0, 0}),
                        available_memory(), options.force);
  refuse_if_too_long(scene, model, timestep,
                     estimate_run(scene, model, timestep, thread_policy().most), options.force);
  const auto start = Clock::now();
  const StopOnSignals stop_on_signals;
  SettleOutcome settled;
  std::vector<TornBar> tears;

  // A cache that cannot be written whole (a full disk) leaves nothing: the writer removes its
  // temporary folder, and an older cache stays as it was.
  try {
    MotionCacheWriter writer(request, model);
    std::optional<EnergyCsv> energy_csv;
    CacheManifest manifest;
    if (options.energy) {
      energy_csv.emplace(writer.file_path("energy.csv"));
      manifest.energy.columns.assign(kEnergyColumns.begin(), kEnergyColumns.end());
    }
    std::vector<Vec3f> positions;
    Progress progress(request.frame_count, !options.quiet, "simulate");
    try {
      run_dynamics(
          model, timestep, request.frame_count, options.energy,
          [&](int frame, const State& state) {
            stop_if_asked();
            positions_for_render(state.x, positions);
            if (frame == 1) {
              settled = state.settled;
            }
            record_tears(model, state, frame, tears);
            writer.add_frame(positions);
            if (energy_csv) {
              const EnergyReport& report = state.energy_workspace.last;
              energy_csv->write(report);
              const auto row = energy_row(report);
              manifest.energy.rows.emplace_back(row.begin(), row.end());
            }
            progress.update(frame, fmt::format("t = {:.2f} s", state.time));
          },
          request.instant_offsets,
          [&](int, int, const State& state) {
            positions_for_render(state.x, positions);
            writer.add_instant(positions);
          });
    } catch (const Interrupted& e) {
      progress.finish();
      throw Interrupted(e.signal(), fmt::format("no cache was written ({} is as it was)",
                                                request.folder.string()));
    }
    progress.finish();
    if (energy_csv) {
      energy_csv->close();
    }
    for (const TornBar& tear : tears) {
      manifest.tears.push_back({tear.frame, tear.n0, tear.n1});
    }
    manifest.scene_path = canonical_scene_path(scene.source);
    manifest.scene_name = scene.name;
    manifest.scene_sha256 = scene.source_sha256;
    manifest.motion_settings = scene.motion_settings;
    manifest.timestep = timestep.dt;
    manifest.steps_per_frame = timestep.steps_per_frame;
    manifest.simulate_seconds = seconds_since(start);
    // A signal after the last frame's check still stops the run before the cache takes its name.
    stop_if_asked();
    writer.commit(std::move(manifest), drawn_wire_radii(model, writer.frame_bounds()));
  } catch (const Interrupted&) {
    throw;
  } catch (const RuntimeError& e) {
    const bool write_failed = dynamic_cast<const WriteError*>(&e) != nullptr;
    throw RuntimeError(fmt::format("{}; no cache was written ({} is as it was){}", e.what(),
                                   request.folder.string(),
                                   write_failed ? ". Free some space there or write the cache "
                                                  "elsewhere (-o)"
                                                : ""));
  }
  if (!options.quiet) {
    if (const std::string line = settle_summary(settled, timestep.dt); !line.empty()) {
      fmt::print("dinam: {}\n", line);
    }
    std::vector<std::string> formats;
    for (const auto& [wanted, name] : {std::pair{request.pc2, "PC2"}, std::pair{request.mdd, "MDD"},
                                       std::pair{request.usd, "USD"}}) {
      if (wanted) {
        formats.emplace_back(name);
      }
    }
    fmt::print("dinam: motion cache of {} in {} ({}, {}; {:.2f} s)\n",
               counted(request.frame_count, "frame"), request.folder.string(),
               counted(static_cast<long long>(model.objects.size()), "object"),
               fmt::join(formats, ", "), seconds_since(start));
  }
  return kExitOk;
}

Command add_simulate_command(CLI::App& app, std::optional<int>& threads) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* simulate_command = app.add_subcommand(
      "simulate",
      "Simulate a scene once into a motion cache: per object a rest mesh (OBJ) and point caches "
      "(PC2, MDD) that 'render --cache' draws from and Blender, Houdini and 3ds Max open, plus "
      "manifest.json");
  simulate_command->add_option("scene", options->scene, "Scene file (YAML)")->required();
  add_optional_option(*simulate_command, "-o,--output", options->output,
                      "Cache folder (default: the scene's 'output'/cache); an older "
                      "cache there is replaced when the new one is complete");
  simulate_command
      ->add_option(
          "--format", options->formats,
          "What the cache holds beside the rest meshes: a list of pc2, mdd (point caches) and "
          "usd (a USD stage of every object)")
      ->default_val(options->formats);
  simulate_command->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");
  simulate_command->add_flag("--energy", options->energy,
                             "Also record the energy report, one row per frame, in "
                             "manifest.json and energy.csv");
  simulate_command->add_flag("--force", options->force,
                             "Run even when the memory the run needs (see 'dinam info') passes "
                             "what the machine has available, or its run time an hour");
  add_threads_option(*simulate_command, threads);

  return {simulate_command, [options](const ThreadChoice&) { return run_simulate(*options); }};
}

}  // namespace dinam
