// The whole-run figures of bench/notes/performance.md, measured in one run on this machine:
//   cmake --build build --target bench_whole_run && build/bench/bench_whole_run [path/to/dinam]
// Each time is the median of several repetitions; the machine is shared, so compare figures
// from one run only.
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "run/frame_source.hpp"
#include "bench_scenes.hpp"
#include "cache/motion_cache.hpp"
#include "cache/motion_cache_writer.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "io/png_file.hpp"
#include "median_time.hpp"
#include "model/model.hpp"
#include "model_measures.hpp"
#include "render/osmesa_renderer.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

// `steps` steps from the model's initial (for the flag: settled) state on `threads` threads.
double simulate_seconds(const Model& model, double dt, int steps, int threads) {
  set_thread_count(threads);
  State state = initial_state(model, dt);
  return median_seconds(5, [&] {
    for (int s = 0; s < steps; ++s) {
      step(model, dt, {}, state);
    }
  });
}

void report_simulation(const char* name, const Model& model, double dt, int steps) {
  for (const int threads : {1, 2}) {
    const double seconds = simulate_seconds(model, dt, steps, threads);
    fmt::print("{:<34} {} thread{}: {:8.1f} ms for {} steps, {:6.1f} M spring evaluations/s\n",
               name, threads, threads == 1 ? " " : "s", 1e3 * seconds, steps,
               1e-6 * static_cast<double>(spring_count(model)) * steps / seconds);
  }
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  const std::filesystem::path source = DINAM_SOURCE_DIR;
  const std::string program = argc > 1 ? argv[1] : (source / "build/dinam").string();
  fmt::print("dinam whole-run benchmark; {} cores, threads {}\n\n", sysconf(_SC_NPROCESSORS_ONLN),
             thread_count());

  // 1. The paper's flag: 12 000 steps of 0.5 ms from its settled shape.
  const SceneDescription flag_scene = read_scene(source / "scenes/flag.yaml");
  const Model flag = build_model(flag_scene);
  const TimeStep flag_step =
      choose_timestep(flag, flag_scene.timestep, flag_scene.fps, flag_scene.timestep_loc);
  report_simulation("paper flag (254 nodes, 587 bars)", flag, flag_step.dt, 12000);

  // 2. A large flag, and what its model and state cost in memory.
  const SceneDescription large_scene = large_flag_scene();
  const double before = heap_bytes_in_use();
  const Model large = build_model(large_scene);
  const double dt = kAutoTimestepSafety * critical_timestep(large);
  {
    const State state = initial_state(large, dt);
    fmt::print("large flag: {} nodes, {} bars, {} springs; model + state {:.0f} bytes per bar\n",
               large.node_count(), large.bar_count(), spring_count(large),
               (heap_bytes_in_use() - before) / large.bar_count());
  }
  report_simulation("large flag", large, dt, 200);

  // 3. Drawing and PNG encoding of the flag at 1280 × 720 with the scene's quality.
  set_thread_count(2);
  const SimulatedFrames frames = simulate_frames(flag, flag_step, flag_scene.frame_count(), false);
  const std::vector<RenderCamera> cameras = frame_cameras(flag_scene, flag, frames).frames;
  const DrawList list = make_draw_list(flag_scene, flag, motion_bounds(frames.positions));
  OsmesaRenderer renderer(render_settings(flag_scene));
  Image image;
  int frame = 0;
  const double draw = median_seconds(21, [&] {
    renderer.render(list, frames.positions[static_cast<std::size_t>(frame)],
                    cameras[static_cast<std::size_t>(frame)], image);
    frame = (frame + 7) % static_cast<int>(frames.positions.size());
  });
  const std::filesystem::path png = std::filesystem::temp_directory_path() / "dinam_bench.png";
  const double encode = median_seconds(21, [&] { write_png(png, image); });
  std::filesystem::remove(png);
  fmt::print("flag frame 1280x720 (samples {}, shadows {}): draw {:.1f} ms, PNG {:.1f} ms\n",
             flag_scene.quality.samples, flag_scene.quality.shadows, 1e3 * draw, 1e3 * encode);

  // 4. End to end: the 120-frame movie from the scene file, as a user runs it.
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "dinam_bench_out";
  const std::string command = fmt::format("'{}' render '{}' -o '{}' -q", program,
                                          (source / "scenes/flag.yaml").string(), out.string());
  const double end_to_end = median_seconds(3, [&] {
    if (std::system(command.c_str()) != 0) {
      fmt::print(stderr, "failed: {}\n", command);
      std::exit(1);
    }
  });
  std::filesystem::remove_all(out);
  const double draw_and_encode = 120.0 * (draw + encode);
  fmt::print(
      "flag movie, 120 frames to mp4, end to end: {:.2f} s, {:.2f} × the {:.2f} s that drawing "
      "and PNG encoding alone take (120 × (draw + PNG))\n",
      end_to_end, end_to_end / draw_and_encode, draw_and_encode);
  // 5. The motion cache: writing it per frame, reading a frame back, and a 20-frame chunk drawn
  //    from it by `dinam render --cache`, against the drawing and PNG encoding of those frames.
  const std::filesystem::path cache = std::filesystem::temp_directory_path() / "dinam_bench_cache";
  const auto write_cache = [&](const Model& model, const std::vector<std::vector<Vec3f>>& shown) {
    MotionCacheWriter writer(
        {cache, true, false, 20.0, static_cast<int>(shown.size()), {}, 0.0, 1, false, {}}, model);
    for (const auto& positions : shown) {
      writer.add_frame(positions);
    }
    CacheManifest manifest;
    manifest.scene_path = canonical_scene_path(flag_scene.source);
    manifest.motion_settings = flag_scene.motion_settings;
    writer.commit(manifest);
  };
  const double write_flag = median_seconds(5, [&] { write_cache(flag, frames.positions); });
  {
    std::vector<Vec3f> large_positions;
    positions_for_render(large.node_initial_x, large_positions);
    const std::vector<std::vector<Vec3f>> large_frames(120, large_positions);
    const double write_large = median_seconds(5, [&] { write_cache(large, large_frames); });
    const MotionCache large_cache(cache);
    int k = 0;
    const double read_large = median_seconds(21, [&] {
      large_cache.read_frames(1 + k, 1 + k);
      k = (k + 13) % 120;
    });
    fmt::print(
        "motion cache (PC2), per frame: write {:.3f} ms for the paper flag ({} nodes), "
        "{:.2f} ms for the large flag ({} nodes); read one frame of the large flag "
        "{:.2f} ms\n",
        1e3 * write_flag / 120.0, flag.node_count(), 1e3 * write_large / 120.0, large.node_count(),
        1e3 * read_large);
  }
  write_cache(flag, frames.positions);
  const auto chunk_seconds = [&](int first, int last) {
    const std::string chunk_command = fmt::format(
        "'{}' render '{}' --cache '{}' --frames {}-{} -o '{}' --movie none -q", program,
        (source / "scenes/flag.yaml").string(), cache.string(), first, last, out.string());
    return median_seconds(5, [&] {
      if (std::system(chunk_command.c_str()) != 0) {
        fmt::print(stderr, "failed: {}\n", chunk_command);
        std::exit(1);
      }
    });
  };
  // A one-frame chunk less that frame's drawing and PNG: what every process pays before its first
  // frame (OSMesa's context, and llvmpipe compiling its shaders at the first draw).
  const double start_up = chunk_seconds(41, 41) - (draw + encode);
  fmt::print("a render process's start-up (a one-frame chunk less one draw + PNG): {:.2f} s\n",
             start_up);
  for (const int frames_in_chunk : {20, 60}) {
    const double chunk = chunk_seconds(41, 40 + frames_in_chunk);
    const double drawing = frames_in_chunk * (draw + encode);
    fmt::print(
        "{}-frame chunk from the cache (render --cache, 720p, no movie), end to end: "
        "{:.2f} s = {:.2f} × the {:.2f} s that drawing and PNG encoding alone take ({} × "
        "(draw + PNG)), {:.2f} × with the start-up\n",
        frames_in_chunk, chunk, chunk / drawing, drawing, frames_in_chunk,
        chunk / (drawing + start_up));
  }
  std::filesystem::remove_all(out);
  std::filesystem::remove_all(cache);

  // The largest the process ever was (the large flag's model and state are the bulk of it).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  fmt::print("peak resident memory of this program: {:.0f} MB\n",
             static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}
