// Drawing and PNG encoding of one frame of the shipped flag, in its settled-in motion, at the
// sizes users render. Reported as time per frame.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>

#include "bench_scenes.hpp"
#include "dynamics/stability.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "rest_frame.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

struct FlagFrame {
  DrawList draw_list;
  std::vector<Vec3f> positions;
  RenderCamera camera;
};

// The flag one second into its motion, so that the cloth is folded as in most frames.
const FlagFrame& flag_frame() {
  static const FlagFrame frame = [] {
    const SceneDescription scene =
        read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/flag.yaml");
    const Model model = build_model(scene);
    const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
    const SimulatedFrames frames = simulate_frames(model, timestep, scene.frame_count(), false);
    const std::vector<RenderCamera> cameras = frame_cameras(scene, model, frames).frames;
    return FlagFrame{make_draw_list(scene, model, motion_bounds(frames.positions)),
                     frames.positions[20], cameras[20]};
  }();
  return frame;
}

void draw(benchmark::State& bench) {
  const auto width = static_cast<int>(bench.range(0));
  const auto height = static_cast<int>(bench.range(1));
  const auto samples = static_cast<int>(bench.range(2));
  const auto shadow = static_cast<int>(bench.range(3));
  OsmesaRenderer renderer({width, height, samples, shadow, {}});
  const FlagFrame& f = flag_frame();
  Image image;
  renderer.render(f.draw_list, f.positions, f.camera, image);  // warm up
  for (auto _ : bench) {
    renderer.render(f.draw_list, f.positions, f.camera, image);
  }
}
// The flag one second in, at the sizes users render: plain, with 4× multisampling, and with
// multisampling and the 2048² shadow map (the default), and the cost of the supersampling
// alternative.
BENCHMARK(draw)
    ->ArgNames({"w", "h", "msaa", "shadow"})
    ->Args({320, 180, 4, 2048})
    ->Args({1280, 720, 1, 0})
    ->Args({1280, 720, 4, 0})
    ->Args({1280, 720, 1, 2048})
    ->Args({1280, 720, 4, 2048})
    ->Args({1920, 1080, 4, 2048})
    // What 2×2 supersampling of 720p would cost before its downsampling pass: drawing 2560×1440.
    ->Args({2560, 1440, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void encode_png(benchmark::State& bench) {
  OsmesaRenderer renderer({1280, 720, 4, 2048, {}});
  Image image;
  renderer.render(flag_frame().draw_list, flag_frame().positions, flag_frame().camera, image);
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

// The scale sweep's wire lattice (bench_scenes.hpp) from its rest positions, at the default
// quality and 720p: 10⁵ and 10⁶ bars (issue 16: at most 2 s a frame at a million).
void draw_wire_lattice(benchmark::State& bench) {
  const SceneDescription scene =
      scale_scene(ScaleStructure::kWireLattice, static_cast<Index>(bench.range(0)));
  const Model model = build_model(scene);
  const RestFrame frame = rest_frame(scene, model);
  OsmesaRenderer renderer(render_settings(scene));
  Image image;
  renderer.render(frame.list, frame.positions, frame.camera, image);  // warm up
  for (auto _ : bench) {
    renderer.render(frame.list, frame.positions, frame.camera, image);
  }
  bench.counters["bars"] = static_cast<double>(model.bar_count());
}
BENCHMARK(draw_wire_lattice)
    ->ArgName("bars")
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Every shipped scene at its default quality, one second in, at 720p and 1080p; with `coarse`,
// its surfaces drawn as simulated (`subdivide: 0`), which is how they were drawn before
// subdivision: the two in one run are the before and after of its cost.
void draw_shipped_scene(benchmark::State& bench, const std::filesystem::path& path, int width,
                        int height, bool coarse) {
  SceneDescription scene = read_scene(path);
  scene.image_width = width;
  scene.image_height = height;
  if (coarse) {
    for (ObjectDesc& object : scene.objects) {
      object.subdivide = 0;
    }
  }
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const SimulatedFrames frames = simulate_frames(model, timestep, scene.frame_count(), false);
  const std::vector<RenderCamera> cameras = frame_cameras(scene, model, frames).frames;
  const DrawList list = make_draw_list(scene, model, motion_bounds(frames.positions));
  OsmesaRenderer renderer(render_settings(scene));
  const std::size_t frame = std::min<std::size_t>(20, frames.positions.size() - 1);
  Image image;
  renderer.render(list, frames.positions[frame], cameras[frame], image);
  for (auto _ : bench) {
    renderer.render(list, frames.positions[frame], cameras[frame], image);
  }
}

void register_shipped_scenes() {
  const std::filesystem::path folder = std::filesystem::path(DINAM_SOURCE_DIR) / "scenes";
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".yaml") {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  for (const auto& path : scenes) {
    for (const auto& [width, height] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
      for (const bool coarse : {true, false}) {
        benchmark::RegisterBenchmark(fmt::format("scene/{}/{}x{}/{}", path.stem().string(), width,
                                                 height, coarse ? "as_simulated" : "smooth")
                                         .c_str(),
                                     [path, width, height, coarse](benchmark::State& bench) {
                                       draw_shipped_scene(bench, path, width, height, coarse);
                                     })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
  }
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  dinam::register_shipped_scenes();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
