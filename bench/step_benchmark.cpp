// Time of one integration step on the shipped flag, after a warm-up from its initial state.
// Reports spring evaluations per second (items) and, as the counter movie_sim, the time the
// whole 120-frame simulation takes at the scene's step.
#include <benchmark/benchmark.h>

#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

void flag_step(benchmark::State& bench) {
  const SceneDescription scene =
      read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/flag.yaml");
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const ForceSwitches forces;
  State state = initial_state(model, timestep.dt, forces);
  for (int s = 0; s < 2000; ++s) {  // warm up into a deformed, moving state
    step(model, timestep.dt, forces, state);
  }
  for (auto _ : bench) {
    step(model, timestep.dt, forces, state);
  }
  bench.SetItemsProcessed(bench.iterations() * model.bar_count());
  const double steps_per_movie = (scene.frame_count() - 1.0) * timestep.steps_per_frame;
  // kIsRate divides by the elapsed seconds and kInvert flips it: elapsed × steps / iterations,
  // printed in seconds with an SI prefix (90.8m is 90.8 ms).
  bench.counters["movie_sim"] =
      benchmark::Counter(static_cast<double>(bench.iterations()) / steps_per_movie,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["bars"] = model.bar_count();
}
BENCHMARK(flag_step);

}  // namespace
}  // namespace dinam

BENCHMARK_MAIN();
