#include "dynamics/integrator.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "core/thread_team.hpp"
#include "dynamics/contact/contact_candidates.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/spring_kinds.hpp"
#include "dynamics/tearing.hpp"
#include "dynamics/tie_springs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// The largest coordinate a node may reach, in metres. Positions leave the integrator in single
// precision (the point caches, the renderer's vertex buffers), where the square of a coordinate
// (a length, a dot product) overflows past about 1.8e19; a node this far has long left any scene,
// so the run stops here rather than write an infinity.
constexpr double kLargestCoordinate = 1e18;

// Whether a node's position and velocity are ones the rest of dinam can take. NaN fails too.
bool within_range(const Vec3& x, const Vec3& v) {
  return (x.array().abs() < kLargestCoordinate).all() && v.allFinite();
}

// Pinned nodes are skipped: they cannot diverge by themselves (only through 0 × ∞ once a
// neighbour's force has overflowed), and naming the free node that did is what helps the user.
bool diverged_at(const Model& model, const State& state, Index i) {
  return !model.pinned(i) && !within_range(state.x[i], state.velocity[i]);
}

// What the user can change: a load or a start given in the wrong units, else the step.
std::string divergence_fix(const Model& model) {
  constexpr double kLargestPlausibleGravity = 1e3;  // m/s², about 100 g
  if (model.gravity.stableNorm() > kLargestPlausibleGravity) {
    return fmt::format(
        "gravity is {:.3g} m/s² (the scene's 'gravity' key, in m/s²: [0, 0, -9.81] on Earth)",
        model.gravity.stableNorm());
  }
  constexpr double kLargestPlausibleSpeed = 1e4;  // m/s, faster than any projectile
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.node_initial_v[i].stableNorm() > kLargestPlausibleSpeed) {
      return fmt::format("object '{}' starts at {:.3g} m/s (its 'initial_velocity' key, in m/s)",
                         model.objects[model.node_object[i]].name,
                         model.node_initial_v[i].stableNorm());
    }
  }
  return "the time step is too long for the forces at work; use 'timestep: auto' or a shorter "
         "step";
}

[[noreturn]] void report_divergence(const Model& model, const State& state) {
  Index i = 0;
  while (i < model.node_count() && !diverged_at(model, state, i)) {
    ++i;
  }
  if (i == model.node_count()) {  // the positions held; the energy report overflowed
    throw RuntimeError(
        fmt::format("the simulation diverged: its energy is no longer finite at step {} (t = "
                    "{:.6g} s); {}",
                    state.step, state.time, divergence_fix(model)));
  }
  throw RuntimeError(fmt::format(
      "the simulation diverged: node {} of object '{}' is {} at step {} (t = {:.6g} s); {}", i,
      model.objects[model.node_object[i]].name,
      state.velocity[i].allFinite()
          ? fmt::format("{:.3g} m from the origin", state.x[i].stableNorm())
          : std::string("moving at a non-finite velocity"),
      state.step, state.time, divergence_fix(model)));
}

// Δt Σ F_i · v_i with the whole-step velocity v_n = ½ (v_{n−½} + v_{n+½}): the work of a force
// kind over the step around t_n. It is the trapezoid rule ½ (F_n + F_{n+1}) · Δx summed by parts,
// and pairs with the kinetic energy reported at whole steps; F_n · Δt v_{n+½} instead would book
// spurious work in modes that flip sign every step.
double work(const std::vector<Vec3>& force, const std::vector<Vec3>& v_whole, double dt) {
  double w = 0.0;
  for (std::size_t i = 0; i < force.size(); ++i) {
    w += force[i].dot(v_whole[i]);
  }
  return w * dt;
}

// The work of the supports over a step around t_n: a pinned node moves by no force of the model
// (its inverse mass is 0), so its support supplies whatever the structure's force on the node
// (`force`, every kind's) resists, −F·v; a pin that holds still does none. The dissipative and
// driving kinds' shares of F at the pinned node are booked as their own works too, so the
// support's work against a damper is that damper's loss.
double support_work(const Model& model, const std::vector<Vec3>& force,
                    const std::vector<Vec3>& v_whole, double dt) {
  double w = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.pinned(i)) {
      w -= force[i].dot(v_whole[i]);
    }
  }
  return w * dt;
}

// Writes the plastic sets of shared springs that the workers put aside (spring_block.hpp), once
// every worker has read the old ones.
void write_plastic_sets_put_aside(State& state) {
  for (std::vector<PlasticSetUpdate>& updates : state.plastic_set_updates) {
    for (const PlasticSetUpdate& update : updates) {
      *update.slot = update.value;
    }
    updates.clear();
  }
}

// The forces at (x_n, v_{n−½}, t_n) into state.force, but for the kinds found after the team's
// job, by one worker (each member of the team runs it, on the nodes and springs of its own). Every
// kind adds to each node's total in the list's order (force_kinds.hpp). While the energy is
// tracked, the dissipative and driving kinds also keep their own forces in the ledger's arrays,
// for the work they do; that does not change the order of the total's sums.
void add_forces(const Worker& worker, const Model& model, const ForceSwitches& switches,
                const StepOptions& options, State& state, bool update_history, double time) {
  EnergyWorkspace& ledger = state.energy_workspace;
  ForceContext total{model, state, state.force, update_history, nullptr, worker, time};
  // 1. What a kind needs before the totals are cleared (the wind's drag on each face and bar,
  //    into its own arrays; the team meets after it).
  for (const ForceKind* kind : kForceKinds) {
    if (kind->prepare_forces != nullptr && switches.*kind->switched) {
      kind->prepare_forces(total);
    }
  }
  // 2. Node by node, the total starts at zero; then every kind adds its forces.
  for_each_own_node(worker, model.node_count(), [&](Index i) {
    state.force[i].setZero();
    if (ledger.enabled) {
      for (std::vector<Vec3>* part : ledger.force_parts()) {
        (*part)[i].setZero();
      }
    }
  });
  for (const ForceKind* kind : kForceKinds) {
    if (kind->add_forces != nullptr && switches.*kind->switched) {
      kind->add_forces(total, options);
    }
  }
}

// Whether some kind of force is held as a constraint (`integrator: xpbd`).
bool holds_constraints(const Model& model) {
  return std::any_of(kForceKinds.begin(), kForceKinds.end(),
                     [&](const ForceKind* kind) { return kind->held_as_constraint(model); });
}

// What the projection of the kinds held as constraints took out of the motion's energy around
// t_n, J: the work of its forces, which act at t_n as any force in the step does (v_{n+½} =
// v_{n−½} + h a_n), F = M (x_{n+1} − x̃_{n+1}) / h² (ledger.v_whole holds x̃_{n+1}), booked as
// every force's is, h F·v_n. The kinds held store nothing (rigid, as the paper's bars): a
// conservative constraint's work would be nil, and what it is not is the scheme's.
double energy_projected_out(const Model& model, double dt, const State& state) {
  const std::vector<Vec3>& before = state.energy_workspace.v_whole;  // x̃_{n+1}
  double work = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const Vec3 v_whole = 0.5 * (state.velocity[i] + state.v_next[i]);
    work += (model.node_mass[i] / dt) * (state.x_next[i] - before[i]).dot(v_whole);
  }
  return -work;
}

// Whether some kind that `switches` leaves on adds its forces after the team's job.
bool adds_forces_after_team(const Model& model, const ForceSwitches& switches) {
  return std::any_of(kForceKinds.begin(), kForceKinds.end(), [&](const ForceKind* kind) {
    return kind->add_forces_after_team != nullptr && kind->acts_in(model, switches);
  });
}

// 3. The kinds found after the team's job (contact between objects, whose search shares its loops
//    with the team by itself), on the calling thread.
void add_forces_after_team(const Model& model, const ForceSwitches& switches, State& state,
                           bool update_history, double time) {
  ForceContext total{model, state, state.force, update_history, nullptr, {}, time};
  for (const ForceKind* kind : kForceKinds) {
    if (kind->add_forces_after_team != nullptr && kind->acts_in(model, switches)) {
      kind->add_forces_after_team(total);
    }
  }
}

// Δt Σ F·v_n of every line of the ledger that some kind books on, into its account: each line
// once, however many kinds share it.
void book_ledger_works(const EnergyWorkspace& ledger, double dt, EnergyAccounts& works) {
  std::vector<Vec3> EnergyWorkspace::*booked[2 * kForceKinds.size()] = {};
  std::size_t count = 0;
  for (const ForceKind* kind : kForceKinds) {
    for (const LedgerLine& line : kind->ledger) {
      if (line.force == nullptr ||
          std::find(booked, booked + count, line.force) != booked + count) {
        continue;
      }
      booked[count++] = line.force;
      works.*line.work = work(ledger.*line.force, ledger.v_whole, dt);
    }
  }
}

// The work that the springs' plastic flow dissipated in the step just taken, booked kind by kind
// in spring order while the energy is tracked: the same sum for any thread count.
void book_plastic_flow(State& state) {
  EnergyWorkspace& ledger = state.energy_workspace;
  if (!ledger.enabled) {
    return;
  }
  for (const SpringKind* kind : kSpringKinds) {
    for (const double work : ledger.*kind->flow) {
      state.energy.plastic_dissipation += work;
    }
  }
}

// The integrator's half of a step, by one worker: velocities to n + ½, the energy at t_n while it
// is tracked, positions to n + 1, into state.v_next and state.x_next (its own nodes); the step's
// end swaps them in. Sets `diverged` where a free node leaves the range (within_range) or the
// energy is no longer finite.
void advance(const Worker& worker, const Model& model, double dt, const StepOptions& options,
             State& state, std::atomic<bool>& diverged) {
  EnergyWorkspace& ledger = state.energy_workspace;
  const TeamMember& member = worker.member;
  const Index n = model.node_count();
  // 1. Velocities to n + ½. Pinned nodes have zero inverse mass and zero velocity.
  for_each_own_node(worker, n, [&](Index i) {
    state.v_next[i] = state.velocity[i] + (dt * model.node_inv_mass[i]) * state.force[i];
  });
  // 2. Pinned nodes that follow a path take the velocity that brings them onto it at t_{n+1}.
  if (!options.pins_hold_still) {
    set_driven_velocities(model, static_cast<double>(state.step + 1) * dt, dt, state.x,
                          state.v_next, [&](Index i) { return worker.owns(i); });
  }
  // 2b. The kinds held as constraints (`integrator: xpbd`): the positions the velocities would
  //     give, projected by the leader alone (the same bits on any thread count), kind by kind in
  //     each sweep; the velocities taken from where they end.
  double projected_out = 0.0;  // J, what the projection took out, while the energy is tracked
  if (holds_constraints(model) && !options.bars_as_springs) {
    member.barrier();
    on_leader(member, [&] {
      for (Index i = 0; i < n; ++i) {
        state.x_next[i] = state.x[i] + dt * state.v_next[i];
      }
      if (ledger.enabled) {
        ledger.v_whole = state.x_next;  // x̃_{n+1}, kept to weigh the projection's impulses
      }
      for (int sweep = 0; sweep < kConstraintSweeps; ++sweep) {
        for (const ForceKind* kind : kForceKinds) {
          if (kind->constraint.project != nullptr && kind->held_as_constraint(model)) {
            kind->constraint.project(model, dt, sweep, state);
          }
        }
      }
      for (const ForceKind* kind : kForceKinds) {
        if (kind->constraint.finish != nullptr && kind->held_as_constraint(model)) {
          kind->constraint.finish(model, dt, state);
        }
      }
      for (Index i = 0; i < n; ++i) {
        if (!model.pinned(i)) {
          state.v_next[i] = (state.x_next[i] - state.x[i]) / dt;
        }
      }
      if (ledger.enabled) {
        // Less what the held springs' flow dissipated, which the ledger books as their own
        // (stage 3).
        projected_out = energy_projected_out(model, dt, state);
        for (const ForceKind* kind : kForceKinds) {
          if (kind->spring != nullptr && kind->held_as_constraint(model)) {
            for (const double flow : ledger.*kind->spring->flow) {
              projected_out -= flow;
            }
          }
        }
      }
    });
  }
  // 3. Energy at t_n (velocities averaged across it), and the work of the forces around t_n:
  //    W_n = Δt F_n · v_n covers [t_n − Δt/2, t_n + Δt/2], so the report at t_n counts half of it.
  if (ledger.enabled) {
    member.barrier();
    on_leader(member, [&] {
      book_plastic_flow(state);
      for (Index i = 0; i < n; ++i) {
        ledger.v_whole[i] = 0.5 * (state.velocity[i] + state.v_next[i]);
      }
      EnergyAccounts step_work;
      book_ledger_works(ledger, dt, step_work);
      step_work.support_work = support_work(model, state.force, ledger.v_whole, dt);
      state.energy.add_works(step_work, 0.5);
      state.energy.numerical_dissipation += 0.5 * projected_out;
      ledger.last = energy_report(model, state, ledger.v_whole);
      state.energy.add_works(step_work, 0.5);
      state.energy.numerical_dissipation += 0.5 * projected_out;
      if (!std::isfinite(ledger.last.total)) {
        diverged.store(true, std::memory_order_relaxed);
      }
    });
  }
  // 4. Positions to n + 1, checked on the way. (Pinned nodes are skipped: they cannot diverge by
  //    themselves, only through 0 × ∞ once a neighbour's force has overflowed.)
  bool any = false;
  for_each_own_node(worker, n, [&](Index i) {
    state.x_next[i] = state.x[i] + dt * state.v_next[i];
    any = (!model.pinned(i) && !within_range(state.x_next[i], state.v_next[i])) || any;
  });
  if (any) {
    diverged.store(true, std::memory_order_relaxed);
  }
}

// Between two steps, once, with every worker waiting: the plastic sets put aside are written
// (every worker has read the old ones), the new positions and velocities swapped in, the step
// counted.
void end_step(State& state, double dt) {
  write_plastic_sets_put_aside(state);
  std::swap(state.x, state.x_next);
  std::swap(state.velocity, state.v_next);
  state.step += 1;
  state.time = static_cast<double>(state.step) * dt;
}

}  // namespace

namespace {

void compute_forces_at(const Model& model, const ForceSwitches& switches, State& state,
                       bool update_history, double time, const StepOptions& options = {}) {
  const bool alone = !step_runs_in_parallel(model);
  const WorkSplit* split = share_work(model, state);
  thread_team().run(
      [&](const TeamMember& member) {
        add_forces({member, split}, model, switches, options, state, update_history, time);
      },
      alone);
  write_plastic_sets_put_aside(state);
  add_forces_after_team(model, switches, state, update_history, time);
  if (update_history) {
    book_plastic_flow(state);
  }
}

}  // namespace

void compute_forces(const Model& model, const ForceSwitches& switches, State& state,
                    bool update_history) {
  compute_forces_at(model, switches, state, update_history, state.time);
}

void compute_forces_at(const Model& model, const ForceSwitches& switches, State& state,
                       double time) {
  compute_forces_at(model, switches, state, false, time);
}

void compute_static_forces(const Model& model, const ForceSwitches& switches, State& state) {
  for (Vec3& v : state.velocity) {
    v.setZero();
  }
  const double dt = std::exchange(state.dt, 0.0);
  compute_forces(model, switches, state, false);
  state.dt = dt;
}

void compute_potential_forces(const Model& model, const ForceSwitches& switches, State& state) {
  StepOptions options;
  options.elastic_only = true;
  compute_forces_at(model, switches, state, false, state.time, options);
}

State make_state(const Model& model, bool track_energy) {
  const std::size_t n = model.node_count();
  State state;
  state.x = model.node_initial_x;
  state.velocity = model.node_initial_v;
  state.force.assign(n, Vec3::Zero());
  state.x_next.assign(n, Vec3::Zero());
  state.v_next.assign(n, Vec3::Zero());
  state.bar_lambda.assign(model.bars_are_constraints() ? model.bar_count() : 0, 0.0);
  state.bar_projection.assign(model.bars_are_constraints() ? model.bar_count() : 0, {});
  // Plastic sets only for the kinds that can yield (model.hpp).
  for (const SpringKind* kind : kSpringKinds) {
    (state.*kind->plastic_set).assign(kind->yields(model) ? kind->count(model) : 0, 0.0);
  }
  for (const ForceKind* kind : kForceKinds) {
    if (kind->prepare_state != nullptr) {
      kind->prepare_state(model, state);
    }
  }
  prepare_tearing(model, state);
  place_driven_nodes(model, 0.0, state);
  EnergyWorkspace& ledger = state.energy_workspace;
  ledger.enabled = track_energy;
  if (track_energy) {  // the ledger's arrays exist only then (memory: 144 bytes per node)
    for (std::vector<Vec3>* part : ledger.force_parts()) {
      part->assign(n, Vec3::Zero());
    }
    ledger.v_whole.assign(n, Vec3::Zero());
    // The flow's work of each spring of the kinds that can yield.
    for (const SpringKind* kind : kSpringKinds) {
      (ledger.*kind->flow).assign(kind->yields(model) ? kind->count(model) : 0, 0.0);
    }
  }
  return state;
}

ForceSwitches stepped_switches(const Model& model, ForceSwitches switches) {
  for (const ForceKind* kind : kForceKinds) {
    if (kind->held_as_constraint(model)) {
      switches.*kind->switched = false;
    }
  }
  return switches;
}

void start_leapfrog(const Model& model, double dt, const ForceSwitches& switches, State& state) {
  state.dt = dt;
  compute_forces(model, stepped_switches(model, switches), state, false);
  if (state.energy_workspace.enabled) {  // after the forces: contact between objects finds its
                                         // pairs there
    state.energy_workspace.last = energy_report(model, state, state.velocity);
  }
  for (Index i = 0; i < model.node_count(); ++i) {
    state.velocity[i] -= 0.5 * dt * model.node_inv_mass[i] * state.force[i];
  }
}

bool worth_sharing(const Model& model) {
  return model.bar_count() + model.bend_count() + model.torsion_count() >= kMinParallelItems;
}

bool step_runs_in_parallel(const Model& model) {
  return thread_team().size() > 1 && worth_sharing(model);
}

const WorkSplit* share_work(const Model& model, State& state) {
  if (!step_runs_in_parallel(model)) {
    return nullptr;
  }
  const int members = thread_team().size();
  if (state.work_split.members != members) {
    state.work_split = split_work(model, members);
    state.plastic_set_updates.assign(static_cast<std::size_t>(members), {});
    for (std::vector<PlasticSetUpdate>& updates : state.plastic_set_updates) {
      updates.reserve(static_cast<std::size_t>(state.work_split.shared_springs));
    }
  }
  return &state.work_split;
}

void step(const Model& model, double dt, const ForceSwitches& switches, State& state,
          const StepOptions& options) {
  advance_steps(model, dt, switches, state, 1, options);
}

void advance_steps(const Model& model, double dt, const ForceSwitches& given, State& state,
                   std::int64_t steps, const StepOptions& options) {
  const ForceSwitches switches = options.bars_as_springs ? given : stepped_switches(model, given);
  state.dt = dt;
  const bool alone = !step_runs_in_parallel(model);
  const WorkSplit* split = share_work(model, state);
  std::atomic<bool> diverged{false};
  if (state.x_next.size() != state.x.size()) {  // a state not made by initial_state
    state.x_next.resize(state.x.size());
    state.v_next.resize(state.x.size());
  }
  if (adds_forces_after_team(model, switches)) {
    // Contact between objects searches for its pairs between two jobs of the team.
    for (std::int64_t s = 0; s < steps && !diverged.load(std::memory_order_relaxed); ++s) {
      stop_if_asked();  // the pair search of a large model can take a while each step
      state.dt = dt;
      thread_team().run(
          [&](const TeamMember& member) {
            if (model.can_tear() || model.ties.can_break) {
              on_leader(member, [&] {
                break_overloaded_bars(model, state);
                break_overloaded_ties(model, state);
              });
            }
            add_forces({member, split}, model, switches, options, state, true, state.time);
          },
          alone);
      add_forces_after_team(model, switches, state, true, state.time);
      thread_team().run(
          [&](const TeamMember& member) {
            advance({member, split}, model, dt, options, state, diverged);
          },
          alone);
      end_step(state, dt);
    }
  } else {
    // One job of the team for all the steps: each worker computes its own nodes' forces from
    // x_n and v_{n−½} and writes their x_{n+1} and v_{n+½} beside them, so the threads meet
    // once a step, where the new positions are swapped in (and after the wind's drag, and
    // around what the leader does alone).
    thread_team().run(
        [&](const TeamMember& member) {
          const Worker worker{member, split};
          for (std::int64_t s = 0; s < steps; ++s) {
            // 0. Bars strained past their breaking limit at x_n break, with what stands on them.
            if (model.can_tear() || model.ties.can_break) {
              on_leader(member, [&] {
                break_overloaded_bars(model, state);
                break_overloaded_ties(model, state);
              });
            }
            // 1. Forces at (x_n, v_{n−½}, t_n); plastic sets and contact anchors move on.
            add_forces(worker, model, switches, options, state, true, state.time);
            // 2. Velocities to n + ½, positions to n + 1.
            advance(worker, model, dt, options, state, diverged);
            member.barrier([&] { end_step(state, dt); });
            if (diverged.load(std::memory_order_relaxed)) {
              break;  // every member sees it here, after the barrier
            }
          }
        },
        alone);
  }
  if (diverged.load(std::memory_order_relaxed)) {
    report_divergence(model, state);
  }
}

}  // namespace dinam
