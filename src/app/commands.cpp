#include "app/commands.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <system_error>

#include "app/draw_list_from_model.hpp"
#include "app/energy_csv.hpp"
#include "app/frame_range.hpp"
#include "app/progress.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "io/movie_encoder.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Frame files are numbered from 1 with at least four digits: frame_0001.png.
int frame_number_digits(int frame_count) {
  return std::max(4, static_cast<int>(std::to_string(frame_count).size()));
}

}  // namespace

int run_render(const RenderOptions& options) {
  // Everything that can be wrong with the input is found before the first file is written.
  SceneDescription scene = read_scene(options.scene);
  if (options.size) {
    parse_image_size(*options.size, scene.image_width, scene.image_height);
  }
  const FrameRange range = options.frames ? parse_frame_range(*options.frames, scene.frame_count())
                                          : FrameRange{1, scene.frame_count()};
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const std::filesystem::path folder = options.output.value_or(scene.output);

  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    throw RuntimeError(
        fmt::format("cannot create the output folder {}: {}", folder.string(), ec.message()));
  }

  const DrawList draw_list = make_draw_list(scene, model);
  OsmesaRenderer renderer(scene.image_width, scene.image_height);
  const ForceSwitches forces;
  State state = initial_state(model, timestep.dt, forces, options.energy_csv);
  std::optional<EnergyCsv> energy_csv;
  if (options.energy_csv) {
    energy_csv.emplace(folder / "energy.csv");
    energy_csv->write(state.energy_workspace.last);
  }
  std::vector<Vec3f> positions;
  Image image;
  const int digits = frame_number_digits(scene.frame_count());

  Progress progress(range.count(), !options.quiet);
  double simulate_seconds = 0.0;
  double draw_seconds = 0.0;
  const auto start = Clock::now();
  for (int frame = 1; frame <= range.last; ++frame) {
    // Frame k shows t = (k − 1) / fps.
    const auto simulate_start = Clock::now();
    if (frame > 1) {
      for (int s = 0; s < timestep.steps_per_frame; ++s) {
        step(model, timestep.dt, forces, state);
      }
    }
    simulate_seconds += seconds_since(simulate_start);
    if (energy_csv && frame > 1) {
      energy_csv->write(state.energy_workspace.last);
    }
    if (frame < range.first) {
      continue;
    }
    const auto draw_start = Clock::now();
    positions_for_render(state.x, positions);
    renderer.render(draw_list, positions, image);
    write_png(folder / fmt::format("frame_{:0{}}.png", frame, digits), image);
    draw_seconds += seconds_since(draw_start);
    progress.update(frame - range.first + 1, fmt::format("simulate {:.1f} s, draw {:.1f} s",
                                                         simulate_seconds, draw_seconds));
  }

  progress.finish();
  if (energy_csv) {
    energy_csv->close();
  }

  int exit_code = kExitOk;
  std::string movie_note;
  if (options.video) {
    const std::filesystem::path movie = folder / (scene.name + ".mp4");
    const MovieRequest request{folder / fmt::format("frame_%0{}d.png", digits), range.first,
                               range.count(), scene.fps, movie};
    if (encode_movie(request) == MovieOutcome::kWritten) {
      movie_note = fmt::format(", movie {}", movie.string());
    } else {
      fmt::print(stderr,
                 "dinam: ffmpeg was not found, so no movie was made; the frames are in {}. "
                 "Install it with: sudo apt-get install ffmpeg\n",
                 folder.string());
      exit_code = kExitFailure;
    }
  }
  if (!options.quiet) {
    fmt::print("dinam: {} frames in {}{} ({:.1f} s: simulate {:.2f} s, draw and write {:.2f} s)\n",
               range.count(), folder.string(), movie_note, seconds_since(start), simulate_seconds,
               draw_seconds);
  }
  return exit_code;
}

int run_info(const std::filesystem::path& scene_path) {
  const SceneDescription scene = read_scene(scene_path);
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  Index pinned = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    pinned += model.pinned(i) ? 1 : 0;
  }
  const int frames = scene.frame_count();
  fmt::print("scene            {} ('{}')\n", scene.source.string(), scene.name);
  fmt::print("objects          {}\n", model.objects.size());
  for (const ModelObject& object : model.objects) {
    fmt::print("  {:<14} {} nodes, {} bars\n", object.name, object.node_count, object.bar_count);
  }
  fmt::print("nodes            {} ({} pinned)\n", model.node_count(), pinned);
  fmt::print("bars             {}\n", model.bar_count());
  fmt::print("springs          axial {}, bending {}, torsion {}\n", model.bar_count(),
             model.bend_count(), model.torsion_count());
  fmt::print("no torsion       {} bars (no usable reference neighbour at an end)\n",
             model.bars_without_torsion);
  fmt::print("total mass       {:.6g} kg\n", model.total_mass());
  fmt::print("stability limit  {:.6g} s ((2/ω)(√(1+ζ²) − ζ), ω and ζ bounded from above)\n",
             timestep.critical);
  fmt::print("time step        {:.6g} s ({})\n", timestep.dt,
             timestep.automatic ? fmt::format("auto: at most {} × the limit", kAutoTimestepSafety)
                                : "from the scene, fitted to whole steps per frame");
  fmt::print("steps per frame  {}\n", timestep.steps_per_frame);
  fmt::print("frames           {} at {:g} fps ({:g} s), {} steps in all\n", frames, scene.fps,
             frames / scene.fps, static_cast<long long>(frames - 1) * timestep.steps_per_frame);
  return kExitOk;
}

}  // namespace dinam
