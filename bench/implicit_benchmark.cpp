// The implicit integrator against central differences on one scene, frame by frame (issue 33's
// figures; bench/notes/implicit-integrator.md):
//   cmake --build build --target bench_implicit && build/bench/bench_implicit [SCENE] [--until S]
//       [--explicit-steps N] [--scheme backward_euler|bdf2] [--step S|auto] [--energy] [--costs]
//       [--threads N]
// Without SCENE, the Wuson of the issue (assimp's OFF/Wuson.off fitted to 1 m, a rubber wire
// dropped 0.5 m). Prints each frame's steps, Newton iterations, factorisations and time, then the
// whole run's; central differences are timed over their first N steps (default 2 000) and
// scaled to the run's step count, since running them through takes minutes. --scheme picks the
// implicit formula (default: the scene's), --step its step (`auto`: a quarter of a frame, for a
// scene whose `timestep` is central differences'). --energy prints each frame's mechanical energy
// (kinetic, springs, gravity, the ground's penalty and the fields' potential, which a field
// constant in time has) beside central differences' at the same frame, which are then run
// through: the numerical damping of an undamped scene. --costs measures, instead of the run, what
// src/estimate/implicit_cost.cpp's estimate is made of: an assembly and factorisation of the
// Hessian, a solve, a force evaluation and an energy, against the factor's size. --threads runs
// both integrators on a team of N threads (default 1).
#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "estimate/implicit_cost.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "solver/implicit_integrator.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/potential.hpp"
#include "solver/stiffness_matrix.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The mechanical energy, J, gravity's and the fields' measured from `origin`: kinetic, springs,
// gravity, the ground's penalty, and −m a·(x − origin) of every field (a potential while the field
// is constant in time). Velocities are the state's (v_{n−½} for central differences).
double kinetic_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      energy += 0.5 * model.node_mass[i] * state.velocity[i].squaredNorm();
    }
  }
  return energy;
}

double mechanical_energy(const Model& model, const State& state, const std::vector<Vec3>& origin) {
  ForceSwitches switches;
  switches.fields = switches.wind = switches.axial_dampers = switches.global_damping = false;
  switches.object_contact = false;
  double energy =
      potential_energy(model, state, switches, origin).energy + kinetic_energy(model, state);
  for (const FieldForce& field : model.fields) {
    const double scale = field.profile(state.time);
    for (const Index i : field.nodes) {
      if (!model.pinned(i)) {
        const double mass = field.per_unit_mass ? model.node_mass[i] : 1.0;
        energy -= mass * scale * field.value.dot(state.x[i] - origin[i]);
      }
    }
  }
  return energy;
}

// Times `work` over repeats until about half a second has passed; seconds per repeat.
template <class Work>
double seconds_each(const Work& work) {
  const auto start = std::chrono::steady_clock::now();
  int repeats = 0;
  do {
    work();
    ++repeats;
  } while (seconds_since(start) < 0.5);
  return seconds_since(start) / repeats;
}

// What the implicit integrator's cost estimate (src/estimate/implicit_cost.hpp) is made of,
// measured at the scene's initial state, one thread.
void print_costs(SceneDescription scene) {
  scene.integrator = IntegratorKind::kImplicit;
  const Model model = build_model(scene);
  const HessianFactorSize factor = hessian_factor_size(model);
  const FreeDofs dofs = free_dofs(model);
  State state = make_state(model, false);
  ForceSwitches springs;
  springs.fields = springs.wind = springs.axial_dampers = false;
  springs.global_damping = springs.object_contact = false;
  StiffnessAssembly assembly;
  PositiveDefiniteSolver solver;
  const Eigen::VectorXd shift = free_masses(model, dofs) / (0.0125 * 0.0125);
  const double factorize = seconds_each([&] {
    SparseMatrix system = assembly.assemble(model, state, springs, dofs, Definiteness::kProjected);
    system.diagonal() += shift;
    solver.factorize(system);
  });
  const double assemble = seconds_each(
      [&] { assembly.assemble(model, state, springs, dofs, Definiteness::kProjected); });
  const double assemble_exact =
      seconds_each([&] { assembly.assemble(model, state, springs, dofs, Definiteness::kExact); });
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(dofs.count);
  const double solve = seconds_each([&] { solver.solve(rhs); });
  const double force = seconds_each([&] { compute_static_forces(model, springs, state); });
  const double energy = seconds_each([&] {
    potential_energy(model, state, springs, model.node_initial_x, SpringEnergy::kWithFlow);
  });
  const auto springs_count = model.bar_count() + model.bend_count() + model.torsion_count();
  fmt::print(
      "{} unknowns, {} springs; factor: {:.4g} nonzeros, {:.4g} flops\n"
      "assembly {:.4g} ms ({:.4g} ns a spring; exact, not projected: {:.4g} ms); assembly and "
      "factorisation {:.4g} ms (the "
      "factorisation {:.4g} ns a flop)\nsolve {:.4g} ms ({:.4g} ns a nonzero, forward and back); "
      "forces {:.4g} ms; energy {:.4g} ms\n",
      dofs.count, springs_count, factor.nonzeros, factor.flops, 1e3 * assemble,
      1e9 * assemble / static_cast<double>(springs_count), 1e3 * assemble_exact, 1e3 * factorize,
      1e9 * (factorize - assemble) / factor.flops, 1e3 * solve,
      1e9 * solve / (2.0 * factor.nonzeros), 1e3 * force, 1e3 * energy);
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  std::string scene_path;
  double until = -1.0;
  std::int64_t explicit_steps = 2000;
  std::string scheme;
  std::string implicit_step;
  bool energy = false;
  bool costs = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--scheme") == 0 && i + 1 < argc) {
      scheme = argv[++i];
    } else if (std::strcmp(argv[i], "--step") == 0 && i + 1 < argc) {
      implicit_step = argv[++i];
    } else if (std::strcmp(argv[i], "--energy") == 0) {
      energy = true;
    } else if (std::strcmp(argv[i], "--costs") == 0) {
      costs = true;
    } else if (std::strcmp(argv[i], "--until") == 0 && i + 1 < argc) {
      until = std::stod(argv[++i]);
    } else if (std::strcmp(argv[i], "--explicit-steps") == 0 && i + 1 < argc) {
      explicit_steps = std::stoll(argv[++i]);
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      set_thread_count(std::stoi(argv[++i]));
    } else {
      scene_path = argv[i];
    }
  }
  if (scene_path.empty() && !std::filesystem::exists(kWuson)) {
    fmt::print("{} is missing (Debian's assimp-testmodels)\n", kWuson);
    return 1;
  }
  SceneDescription scene = scene_path.empty() ? wuson_scene() : read_scene(scene_path);
  if (costs) {
    print_costs(scene);
    return 0;
  }
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
  std::vector<double> explicit_energy;  // at each frame, with --energy
  double peak_kinetic = 0.0;            // J, central differences', at the frames
  {
    State state = initial_state(explicit_model, explicit_step.dt);
    const std::vector<Vec3> origin = state.x;
    const std::int64_t taken = energy ? explicit_total : std::min(explicit_steps, explicit_total);
    const auto start = std::chrono::steady_clock::now();
    if (energy) {
      explicit_energy.push_back(mechanical_energy(explicit_model, state, origin));
      for (int frame = 1; frame <= frames; ++frame) {
        advance_steps(explicit_model, explicit_step.dt, {}, state, explicit_step.steps_per_frame);
        explicit_energy.push_back(mechanical_energy(explicit_model, state, origin));
        peak_kinetic = std::max(peak_kinetic, kinetic_energy(explicit_model, state));
      }
    } else {
      advance_steps(explicit_model, explicit_step.dt, {}, state, taken);
    }
    explicit_seconds =
        seconds_since(start) * static_cast<double>(explicit_total) / static_cast<double>(taken);
  }

  // The implicit integrator at its automatic step.
  scene.integrator = IntegratorKind::kImplicit;
  if (scheme == "bdf2") {
    scene.implicit_scheme = ImplicitScheme::kBdf2;
  } else if (scheme == "backward_euler") {
    scene.implicit_scheme = ImplicitScheme::kBackwardEuler;
  }
  if (implicit_step == "auto") {
    scene.timestep.reset();
  } else if (!implicit_step.empty()) {
    scene.timestep = std::stod(implicit_step);
  }
  const Model built = build_model(scene);
  const TimeStep step = choose_timestep(built, scene.timestep, scene.fps, scene.timestep_loc);
  // The ground softened for the run's step, as `dinam simulate` steps it (ImplicitStepper).
  ImplicitIntegrator integrator(built, {.longest_step = step.dt});
  const Model& model = integrator.model();
  const auto steps_per_frame = static_cast<std::int64_t>(std::lround(1.0 / (scene.fps * step.dt)));
  fmt::print("{}: {} nodes, {} bars; {} frames of {:.4g} s; {}, steps of {:.4g} s\n",
             scene_path.empty() ? "Wuson" : scene_path, model.node_count(), model.bar_count(),
             frames, 1.0 / scene.fps,
             model.implicit_scheme == ImplicitScheme::kBdf2 ? "BDF2" : "backward Euler", step.dt);
  State state = initial_state(model, step.dt);
  const std::vector<Vec3> origin = state.x;
  const double first_energy = mechanical_energy(model, state, origin);
  const auto start = std::chrono::steady_clock::now();
  ImplicitStats before;
  for (int frame = 1; frame <= frames; ++frame) {
    const auto frame_start = std::chrono::steady_clock::now();
    integrator.advance(state, step.dt, steps_per_frame);
    const ImplicitStats& now = integrator.stats();
    fmt::print(
        "frame {:3}  t {:6.3f} s  steps {:4}  iterations {:5}  solve iterations {:5}  "
        "factorisations {:4}  {:8.3f} s",
        frame, state.time, now.steps - before.steps, now.iterations - before.iterations,
        now.solve_iterations - before.solve_iterations, now.factorizations - before.factorizations,
        seconds_since(frame_start));
    if (energy) {
      fmt::print("  energy {:+.5g} J (central differences {:+.5g} J; both from {:+.5g} J)",
                 mechanical_energy(model, state, origin) - first_energy,
                 explicit_energy[static_cast<std::size_t>(frame)] - explicit_energy[0],
                 first_energy);
    }
    fmt::print("\n");
    before = now;
  }
  const double implicit_seconds = seconds_since(start);
  const ImplicitStats& stats = integrator.stats();
  fmt::print(
      "\nimplicit, {:.3g} s of motion: {:.2f} s; {} steps ({} split), {} Newton iterations ({} "
      "solve iterations), {} factorisations\n",
      duration, implicit_seconds, stats.steps, stats.splits, stats.iterations,
      stats.solve_iterations, stats.factorizations);
  fmt::print(
      "central differences: {} steps of {:.3g} s, about {:.2f} s (timed over the first {}); "
      "{:.3g}× the implicit\n",
      explicit_total, explicit_step.dt, explicit_seconds,
      energy ? explicit_total : std::min(explicit_steps, explicit_total),
      explicit_seconds / implicit_seconds);
  if (energy) {
    fmt::print("central differences' largest kinetic energy at a frame: {:.4g} J\n", peak_kinetic);
  }
  return 0;
}
