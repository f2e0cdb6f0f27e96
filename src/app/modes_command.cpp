// `dinam modes`: at what frequencies a scene's structure sways, and how. The lowest natural modes
// about its static equilibrium under gravity (settled as the scene's `settle` asks, or by
// Newton's method by default), printed as a table and written as a motion cache with one object
// per mode, each oscillating in its shape, that Blender opens like any other cache.
#include <fmt/format.h>

#include <memory>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "cache/motion_cache_writer.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/stop_request.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"
#include "solver/natural_modes.hpp"
#include "solver/settle.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

// The cache shows each mode through one cycle in this many frames at this rate (2 s), whatever
// its frequency, so that a slow sway and a fast flutter both read at a glance and loop.
constexpr double kCycleFps = 24.0;
constexpr int kCycleFrames = 48;
// The largest node excursion of each mode in the cache, as a share of the structure's size.
constexpr double kAmplitudeShare = 0.1;

// The whole structure once per mode: mode k's nodes are the model's nodes, all objects together,
// at k × n_nodes onwards, with the model's bars and faces; the first `count` of `modes`.
Model mode_objects(const Model& model, const std::vector<Vec3>& equilibrium,
                   const std::vector<NaturalMode>& modes) {
  Model shown;
  const Index n = model.node_count();
  shown.face_offsets.push_back(0);
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const Index offset = static_cast<Index>(m) * n;
    ModelObject object;
    object.name = fmt::format("mode_{:02}_{:.4g}Hz", m + 1, modes[m].frequency);
    object.first_node = offset;
    object.node_count = n;
    object.first_bar = static_cast<Index>(m) * model.bar_count();
    object.bar_count = model.bar_count();
    shown.objects.push_back(object);
    for (Index i = 0; i < n; ++i) {
      shown.node_initial_x.push_back(equilibrium[i]);
      shown.node_mass.push_back(model.node_mass[i]);
      shown.node_object.push_back(static_cast<Index>(m));
    }
    for (const Index node : model.bar_nodes) {
      shown.bar_nodes.push_back(node + offset);
    }
    shown.bar_on_face.insert(shown.bar_on_face.end(), model.bar_on_face.begin(),
                             model.bar_on_face.end());
    for (Index f = 0; f < model.face_count(); ++f) {
      for (Index k = model.face_offsets[f]; k < model.face_offsets[f + 1]; ++k) {
        shown.face_nodes.push_back(model.face_nodes[k] + offset);
      }
      shown.face_offsets.push_back(static_cast<Index>(shown.face_nodes.size()));
    }
  }
  return shown;
}

double structure_size(const std::vector<Vec3>& x) {
  Vec3 low = x.front();
  Vec3 high = x.front();
  for (const Vec3& p : x) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// Each mode's amplitude (m per unit of its shape) for an excursion of kAmplitudeShare × size.
std::vector<double> amplitudes(const std::vector<NaturalMode>& modes, double size) {
  std::vector<double> result;
  for (const NaturalMode& mode : modes) {
    double largest = 0.0;
    for (const Vec3& d : mode.shape) {
      largest = std::max(largest, d.norm());
    }
    result.push_back(largest > 0.0 ? kAmplitudeShare * size / largest : 0.0);
  }
  return result;
}

void print_table(const std::vector<NaturalMode>& modes) {
  fmt::print("mode  frequency (Hz)  period (s)   mass share x      y      z\n");
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const NaturalMode& mode = modes[m];
    const std::string period =
        mode.frequency > 0.0 ? fmt::format("{:10.4g}", 1.0 / mode.frequency) : "         -";
    const std::string frequency =
        mode.free                   ? fmt::format("{:>14}", "0 (free)")  // a rigid-body motion
        : mode.omega_squared >= 0.0 ? fmt::format("{:14.5g}", mode.frequency)
                                    : fmt::format("{:>14}", "unstable");  // ω² < 0
    fmt::print("{:4}  {}  {}   {:9.1f} % {:5.1f} % {:5.1f} %\n", m + 1, frequency, period,
               100.0 * mode.mass_share.x(), 100.0 * mode.mass_share.y(),
               100.0 * mode.mass_share.z());
  }
}

void write_modes_csv(const std::filesystem::path& path, const std::vector<NaturalMode>& modes,
                     const std::vector<double>& shown_amplitudes) {
  std::string text =
      "mode,frequency_hz,period_s,omega_squared,mass_share_x,mass_share_y,"
      "mass_share_z,amplitude_shown,free\n";
  for (std::size_t m = 0; m < modes.size(); ++m) {
    const NaturalMode& mode = modes[m];
    text += fmt::format("{},{},{},{},{},{},{},{},{}\n", m + 1, mode.frequency,
                        mode.frequency > 0.0 ? 1.0 / mode.frequency : 0.0, mode.omega_squared,
                        mode.mass_share.x(), mode.mass_share.y(), mode.mass_share.z(),
                        shown_amplitudes[m], mode.free ? 1 : 0);
  }
  write_output_file(path, text, "the table of modes");
}

}  // namespace

int run_modes(const ModesOptions& options) {
  SceneDescription scene = read_scene(options.scene);
  // Modes are about an equilibrium: the scene's own settle, or Newton's method by default.
  scene.settle.enabled = true;
  const Model model = build_model_telling_warnings(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  CacheRequest request;
  request.folder = options.output.value_or(scene.output / "modes");
  check_output_place(request.folder, OutputPlace::kBeside,
                     options.output ? "-o" : "the cache folder");
  request.fps = kCycleFps;
  request.frame_count = kCycleFrames;
  const auto start = Clock::now();
  // SIGINT and SIGTERM stop the settle and the eigensolver where they check; the cache is written
  // whole (its temporary folder removed as the run unwinds) or not at all.
  const StopOnSignals stop_on_signals;

  State state = make_state(model, false);
  settle_under_gravity(model, settling_step(model, timestep.dt), {}, state);
  ForceSwitches quiet;
  quiet.fields = false;
  quiet.wind = false;
  // What the eigensolver cannot do is told at the scene, as every other error of the command is.
  std::vector<NaturalMode> modes;
  try {
    modes = natural_modes(model, state, quiet, options.count);
  } catch (const RuntimeError& e) {
    throw UserError(FileLoc{options.scene.string()}, e.what());
  }
  if (modes.empty()) {
    throw_user_error(FileLoc{options.scene.string()},
                     "every node is pinned, so nothing can vibrate; unpin some ('pinned'), or "
                     "give an object 'role: flexible'");
  }
  if (!options.quiet) {
    fmt::print("dinam: {}\n", settle_summary(state.settled, timestep.dt));
    print_table(modes);
  }

  const Model shown = mode_objects(model, state.x, modes);
  const std::vector<double> shown_amplitudes = amplitudes(modes, structure_size(state.x));
  MotionCacheWriter writer(request, shown);
  std::vector<Vec3f> positions(static_cast<std::size_t>(shown.node_count()));
  for (int frame = 0; frame < kCycleFrames; ++frame) {
    const double phase = std::sin(2.0 * std::numbers::pi * frame / kCycleFrames);
    for (std::size_t m = 0; m < modes.size(); ++m) {
      const std::size_t offset = m * static_cast<std::size_t>(model.node_count());
      for (Index i = 0; i < model.node_count(); ++i) {
        positions[offset + i] =
            (state.x[i] + phase * shown_amplitudes[m] * modes[m].shape[i]).cast<float>();
      }
    }
    writer.add_frame(positions);
  }
  write_modes_csv(writer.file_path("modes.csv"), modes, shown_amplitudes);
  stop_if_asked();  // before the cache takes its name
  CacheManifest manifest;
  manifest.scene_path = canonical_scene_path(scene.source);
  manifest.scene_name = scene.name;
  manifest.scene_sha256 = scene.source_sha256;
  manifest.motion_settings = scene.motion_settings;
  manifest.simulate_seconds = seconds_since(start);
  writer.commit(std::move(manifest));
  if (!options.quiet) {
    fmt::print(
        "dinam: {} modes in {} (one object each, one cycle in {} frames at {:g} fps; "
        "modes.csv; {:.2f} s)\n",
        modes.size(), request.folder.string(), kCycleFrames, kCycleFps, seconds_since(start));
  }
  return kExitOk;
}

Command add_modes_command(CLI::App& app, std::optional<int>& threads) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* modes_command = app.add_subcommand(
      "modes",
      "Print the lowest natural frequencies and mode shapes of a scene's structure at rest under "
      "gravity, and write them as a motion cache (one object per mode)");
  modes_command->add_option("scene", options->scene, "Scene file (YAML)")->required();
  modes_command->add_option("--count", options->count, "How many of the lowest modes")
      ->default_val(options->count)
      ->check(CLI::Range(1, 1000));
  add_optional_option(*modes_command, "-o,--output", options->output,
                      "Cache folder to write (default: the scene's output folder/modes)");
  modes_command->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");
  add_threads_option(*modes_command, threads);

  return {modes_command, [options](const ThreadChoice&) { return run_modes(*options); }};
}

}  // namespace dinam
