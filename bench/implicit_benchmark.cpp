// The implicit integrator against central differences on one scene, frame by frame (issue 33's
// figures; docs/performance.md, "The implicit integrator"):
//   cmake --build build --target bench_implicit && build/bench/bench_implicit [SCENE] [--until S]
//       [--explicit-steps N]
// Without SCENE, the Wuson of the issue (assimp's OFF/Wuson.off fitted to 1 m, a rubber wire
// dropped 0.5 m). Prints each frame's steps, Newton iterations, factorisations and time, then the
// whole run's; central differences are timed over their first N steps (default 2 000) and
// scaled to the run's step count, since running them through takes minutes.
#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench_scenes.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "solver/implicit_integrator.hpp"
#include "solver/initial_state.hpp"

namespace dinam {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  std::string scene_path;
  double until = -1.0;
  std::int64_t explicit_steps = 2000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--until") == 0 && i + 1 < argc) {
      until = std::stod(argv[++i]);
    } else if (std::strcmp(argv[i], "--explicit-steps") == 0 && i + 1 < argc) {
      explicit_steps = std::stoll(argv[++i]);
    } else {
      scene_path = argv[i];
    }
  }
  if (scene_path.empty() && !std::filesystem::exists(kWuson)) {
    fmt::print("{} is missing (Debian's assimp-testmodels)\n", kWuson);
    return 1;
  }
  SceneDescription scene = scene_path.empty() ? wuson_scene() : read_scene(scene_path);
  const double duration = until > 0.0 ? until : scene.duration;
  const int frames = static_cast<int>(std::lround(duration * scene.fps));

  // Central differences: the scene as it is, with its automatic step.
  scene.integrator = IntegratorKind::kCentralDifference;
  const Model explicit_model = build_model(scene);
  const TimeStep explicit_step =
      choose_timestep(explicit_model, scene.timestep, scene.fps, scene.timestep_loc);
  const std::int64_t explicit_total =
      static_cast<std::int64_t>(std::ceil(duration / explicit_step.dt));
  double explicit_seconds = 0.0;
  {
    State state = initial_state(explicit_model, explicit_step.dt);
    const std::int64_t taken = std::min(explicit_steps, explicit_total);
    const auto start = std::chrono::steady_clock::now();
    advance_steps(explicit_model, explicit_step.dt, {}, state, taken);
    explicit_seconds =
        seconds_since(start) * static_cast<double>(explicit_total) / static_cast<double>(taken);
  }

  // The implicit integrator at its automatic step.
  scene.integrator = IntegratorKind::kImplicit;
  const Model model = build_model(scene);
  const TimeStep step = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const auto steps_per_frame = static_cast<std::int64_t>(std::lround(1.0 / (scene.fps * step.dt)));
  fmt::print("{}: {} nodes, {} bars; {} frames of {:.4g} s\n",
             scene_path.empty() ? "Wuson" : scene_path, model.node_count(), model.bar_count(),
             frames, 1.0 / scene.fps);
  State state = initial_state(model, step.dt);
  ImplicitIntegrator integrator(model);
  const auto start = std::chrono::steady_clock::now();
  ImplicitStats before;
  for (int frame = 1; frame <= frames; ++frame) {
    const auto frame_start = std::chrono::steady_clock::now();
    integrator.advance(state, step.dt, steps_per_frame);
    const ImplicitStats& now = integrator.stats();
    fmt::print(
        "frame {:3}  t {:6.3f} s  steps {:4}  iterations {:5}  factorisations {:4}  "
        "{:8.3f} s\n",
        frame, state.time, now.steps - before.steps, now.iterations - before.iterations,
        now.factorizations - before.factorizations, seconds_since(frame_start));
    before = now;
  }
  const double implicit_seconds = seconds_since(start);
  const ImplicitStats& stats = integrator.stats();
  fmt::print(
      "\nimplicit, {:.3g} s of motion: {:.2f} s; {} steps ({} split), {} Newton iterations, {} "
      "factorisations\n",
      duration, implicit_seconds, stats.steps, stats.splits, stats.iterations,
      stats.factorizations);
  fmt::print(
      "central differences: {} steps of {:.3g} s, about {:.2f} s (timed over the first {}); "
      "{:.1f}× the implicit\n",
      explicit_total, explicit_step.dt, explicit_seconds, std::min(explicit_steps, explicit_total),
      explicit_seconds / implicit_seconds);
  return 0;
}
