// Drawing and PNG encoding of one frame of the shipped flag, in its settled-in motion, at the
// sizes users render. Reported as time per frame.
#include <benchmark/benchmark.h>

#include "app/draw_list_from_model.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

struct FlagFrame {
  DrawList draw_list;
  std::vector<Vec3f> positions;
};

// The flag one second into its motion, so that the cloth is folded as in most frames.
const FlagFrame& flag_frame() {
  static const FlagFrame frame = [] {
    const SceneDescription scene =
        read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/flag.yaml");
    const Model model = build_model(scene);
    const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
    State state = initial_state(model, timestep.dt);
    for (int s = 0; s < 20 * timestep.steps_per_frame; ++s) {
      step(model, timestep.dt, {}, state);
    }
    FlagFrame f{make_draw_list(scene, model), {}};
    positions_for_render(state.x, f.positions);
    return f;
  }();
  return frame;
}

void draw(benchmark::State& bench) {
  const auto width = static_cast<int>(bench.range(0));
  const auto height = static_cast<int>(bench.range(1));
  const auto samples = static_cast<int>(bench.range(2));
  OsmesaRenderer renderer(width, height, samples);
  Image image;
  renderer.render(flag_frame().draw_list, flag_frame().positions, image);  // warm up
  for (auto _ : bench) {
    renderer.render(flag_frame().draw_list, flag_frame().positions, image);
  }
}
BENCHMARK(draw)
    ->ArgNames({"w", "h", "msaa"})
    ->Args({320, 180, 4})
    ->Args({1280, 720, 1})
    ->Args({1280, 720, 4})
    ->Args({1920, 1080, 4})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void encode_png(benchmark::State& bench) {
  OsmesaRenderer renderer(1280, 720);
  Image image;
  renderer.render(flag_frame().draw_list, flag_frame().positions, image);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "dinam_bench.png";
  const PngOptions options{static_cast<int>(bench.range(0)), bench.range(1) != 0};
  for (auto _ : bench) {
    write_png(path, image, options);
  }
  std::filesystem::remove(path);
}
BENCHMARK(encode_png)
    ->ArgNames({"level", "filter"})
    ->Args({1, 0})
    ->Args({6, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace dinam

BENCHMARK_MAIN();
