// The integration step and the spring kernels, with Google Benchmark:
//   cmake --build build --target bench_step && build/bench/bench_step
// flag_step is one step of the paper's flag (its counter movie_sim: the 12 000 steps of its
// movie at that rate); the kernel benchmarks add one kind of spring force over the large flag
// (about 100 000 of each kind), on 1 and 2 OpenMP threads, as spring evaluations per second.
#include <benchmark/benchmark.h>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/torsion_spring.hpp"
#include "dynamics/work_split.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"

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
  bench.SetItemsProcessed(bench.iterations() *
                          (model.bar_count() + model.bend_count() + model.torsion_count()));
  const double steps_per_movie = (scene.frame_count() - 1.0) * timestep.steps_per_frame;
  // kIsRate divides by the elapsed seconds and kInvert flips it: elapsed × steps / iterations,
  // printed in seconds with an SI prefix (90.8m is 90.8 ms).
  bench.counters["movie_sim"] =
      benchmark::Counter(static_cast<double>(bench.iterations()) / steps_per_movie,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["bars"] = model.bar_count();
}
BENCHMARK(flag_step);

// The large flag (with torsion springs), 50 steps into its fall so that every spring is loaded.
struct LargeFlag {
  Model model;
  State state;
  LargeFlag() : model(build_model(large_flag_scene(true))) {
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    state = initial_state(model, dt);
    for (int s = 0; s < 50; ++s) {
      step(model, dt, {}, state);
    }
  }
};

const LargeFlag& large_flag() {
  static const LargeFlag flag;
  return flag;
}

// One kind's forces added over the whole large flag per iteration; range(0) is the thread count.
template <void (*AddForces)(ForceContext&), Index (Model::*Count)() const>
void spring_kernel(benchmark::State& bench) {
  const LargeFlag& flag = large_flag();
  State state = flag.state;
  set_thread_count(static_cast<int>(bench.range(0)));
  const WorkSplit* split = share_work(flag.model, state);
  for (auto _ : bench) {
    thread_team().run([&](const TeamMember& member) {
      ForceContext context{flag.model, state,           state.force, false,
                           nullptr,    {member, split}, state.time};
      AddForces(context);
    });
    benchmark::DoNotOptimize(state.force.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(bench.iterations() * (flag.model.*Count)());
}
BENCHMARK(spring_kernel<add_axial_spring_forces, &Model::bar_count>)
    ->Name("axial_springs")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK(spring_kernel<add_bending_spring_forces, &Model::bend_count>)
    ->Name("bending_springs")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();
BENCHMARK(spring_kernel<add_torsion_spring_forces, &Model::torsion_count>)
    ->Name("torsion_springs")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime();

}  // namespace
}  // namespace dinam

BENCHMARK_MAIN();
