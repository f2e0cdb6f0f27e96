// The settling phase by Newton's method against dynamic relaxation, and the natural modes, in one
// run on this machine (issue 30's figures; bench/notes/performance.md, "Settling and modes"):
//   cmake --build build --target bench_settle && build/bench/bench_settle [--large] [--modes]
// For the paper's flag: each method's time, its work (iterations or steps), the potential energy
// it reached, the largest distance of a node from relaxation's shape, and the settle against the
// 12 000-step animation that follows it. With --large, the same for the large flag (97 560 bars,
// minutes by relaxation); with --modes, the lowest ten modes of the large flag. One thread: the
// settle's share of a run, as the issue measures it.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "median_time.hpp"
#include "model/model.hpp"
#include "solver/natural_modes.hpp"
#include "solver/potential.hpp"
#include "solver/settle.hpp"
#include "solver/stiffness_matrix.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

struct Settled {
  double seconds = 0.0;
  State state;
};

Settled settle_with(const SceneDescription& scene, SettleMethod method, int repeats, double dt) {
  SceneDescription copy = scene;
  copy.settle.enabled = true;
  copy.settle.method = method;
  const Model model = build_model(copy);
  Settled settled;
  settled.seconds = median_seconds(repeats, [&] {
    settled.state = make_state(model, false);
    settle_under_gravity(model, dt, {}, settled.state);
  });
  return settled;
}

double largest_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, (a[i] - b[i]).norm());
  }
  return largest;
}

void compare(const char* name, const SceneDescription& scene, double dt, int repeats,
             double animation_seconds) {
  const Model model = build_model(scene);
  const std::vector<Vec3>& mesh = model.node_initial_x;
  auto energy = [&](const State& state) { return potential_energy(model, state, {}, mesh).energy; };
  const Settled relaxed = settle_with(scene, SettleMethod::kRelax, repeats, dt);
  const Settled newton = settle_with(scene, SettleMethod::kNewton, repeats, dt);
  fmt::print("{}: {} nodes, {} bars, {} springs\n", name, model.node_count(), model.bar_count(),
             model.bar_count() + model.bend_count() + model.torsion_count());
  const SettleOutcome& r = relaxed.state.settled;
  fmt::print(
      "  relaxation  {:9.3f} s  {} steps of {:g} ms ({} restarts), residual {:.2g}, "
      "potential energy {:.6f} J\n",
      relaxed.seconds, r.steps, 1e3 * dt, r.restarts, r.residual, energy(relaxed.state));
  const SettleOutcome& n = newton.state.settled;
  fmt::print(
      "  Newton      {:9.3f} s  {} iterations{}, residual {:.2g}, potential energy {:.6f} "
      "J\n",
      newton.seconds, n.newton_iterations,
      n.by_newton ? "" : " (fell back to relaxation: " + n.fallback + ")", n.residual,
      energy(newton.state));
  fmt::print("  Newton {:.1f}x faster; largest node distance from relaxation's shape {:.4f} m\n",
             relaxed.seconds / newton.seconds, largest_distance(newton.state.x, relaxed.state.x));
  if (animation_seconds > 0.0) {
    fmt::print(
        "  the settle against the animation ({:.3f} s): relaxation {:.0f} %, Newton {:.1f} "
        "%\n",
        animation_seconds, 100.0 * relaxed.seconds / animation_seconds,
        100.0 * newton.seconds / animation_seconds);
  }
  // Out now: the large flag's comparison that follows runs for many minutes, and a run cut short
  // would lose the figures still in the buffer.
  std::fflush(stdout);
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  bool large = false;
  bool modes = false;
  for (int a = 1; a < argc; ++a) {
    large = large || std::strcmp(argv[a], "--large") == 0;
    modes = modes || std::strcmp(argv[a], "--modes") == 0;
  }
  set_thread_count(1);
  const std::filesystem::path source = DINAM_SOURCE_DIR;

  // 1. The paper's flag, and its 12 000-step animation from the settled shape.
  const SceneDescription flag_scene = read_scene(source / "scenes/flag.yaml");
  const Model flag = build_model(flag_scene);
  const TimeStep flag_step =
      choose_timestep(flag, flag_scene.timestep, flag_scene.fps, flag_scene.timestep_loc);
  State start = make_state(flag, false);
  start_leapfrog(flag, flag_step.dt, {}, start);
  const double animation = median_seconds(3, [&] {
    State state = start;
    advance_steps(flag, flag_step.dt, {}, state, 12000);
  });
  compare("paper flag", flag_scene, flag_step.dt, 5, animation);

  // 2. The large flag hung from one edge.
  if (large) {
    const SceneDescription large_scene = large_flag_scene();
    const Model model = build_model(large_scene);
    compare("large flag", large_scene, kAutoTimestepSafety * critical_timestep(model), 1, 0.0);
  }
  // 3. The lowest ten modes of the large flag, about its mesh without gravity (an equilibrium
  //    already, so that the figure is the modes' alone).
  if (modes) {
    SceneDescription scene = large_flag_scene();
    scene.gravity = Vec3::Zero();
    const Model model = build_model(scene);
    const State state = make_state(model, false);
    std::vector<NaturalMode> found;
    const double seconds = median_seconds(1, [&] { found = natural_modes(model, state, {}, 10); });
    fmt::print(
        "large flag, the lowest 10 modes: {:.2f} s ({} free unknowns); {:.4g} to {:.4g} Hz\n",
        seconds, free_dofs(model).count, found.front().frequency, found.back().frequency);
  }
  return 0;
}
