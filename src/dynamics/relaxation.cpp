#include "dynamics/relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/stop_request.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

constexpr double kStandardGravity = 9.80665;  // m/s², the weight scale where the model has none

// Steps between residual checks while no kinetic-energy peak comes (a slow, steady creep); the
// last step is always checked.
constexpr std::int64_t kCheckInterval = 1000;

// The viscous stage hands over to kinetic damping once every node carries all but this fraction of
// its weight: past the large, nonlinear part of the motion, where the path decides the shape.
constexpr double kViscousHandover = 0.1;

// Steps between residual checks in the viscous stage (each check is one more force evaluation).
constexpr std::int64_t kViscousCheckInterval = 100;

double kinetic_measure(const Model& model, const State& state) {
  double sum = 0.0;  // Σ m v², serial: the restarts must not depend on the thread count
  for (Index i = 0; i < model.node_count(); ++i) {
    sum += model.node_mass[i] * state.velocity[i].squaredNorm();
  }
  return sum;
}

}  // namespace

std::pair<double, Index> relative_residual(const Model& model, const State& state) {
  const double g = model.gravity.norm() > 0.0 ? model.gravity.norm() : kStandardGravity;
  double largest = 0.0;
  Index worst = -1;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.pinned(i)) {
      continue;
    }
    const double r = state.force[i].norm() / (model.node_mass[i] * g);
    if (!(r <= largest)) {  // NaN counts as the worst
      largest = r;
      worst = i;
    }
  }
  return {largest, worst};
}

namespace {

// The diagonal of the free nodes' box (0 when none is free).
double free_size(const Model& model) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      low = low.cwiseMin(model.node_initial_x[i]);
      high = high.cwiseMax(model.node_initial_x[i]);
    }
  }
  return low.x() <= high.x() ? (high - low).norm() : 0.0;
}

double gravity_or_standard(const Model& model) {
  return model.gravity.norm() > 0.0 ? model.gravity.norm() : kStandardGravity;
}

}  // namespace

double automatic_settle_damping(const Model& model) {
  const double size = free_size(model);
  return size > 0.0 ? 8.0 * std::sqrt(gravity_or_standard(model) / size) : 0.0;
}

double expected_relaxation_seconds(const Model& model) {
  const double size = free_size(model);
  double damping = model.settle.damping.value_or(automatic_settle_damping(model));
  if (damping <= 0.0) {  // no creep: kinetic damping alone, taken to be as long
    damping = automatic_settle_damping(model);
  }
  const double time_constant = damping * size / gravity_or_standard(model);
  return std::min(2.0 * 2.3 * time_constant, model.settle.duration);
}

std::int64_t relax_viscously(const Model& model, double dt, const ForceSwitches& switches,
                             const StepOptions& options, double damping, std::int64_t max_steps,
                             double handover, State& state, SettleOutcome& outcome) {
  StepOptions damped = options;
  damped.global_damping = damping;
  for (std::int64_t s = 1; s <= max_steps; ++s) {
    step(model, dt, switches, state, damped);
    if (s % kViscousCheckInterval == 0 || s == max_steps) {
      stop_if_asked();
      std::vector<Vec3> velocities = state.velocity;
      compute_static_forces(model, switches, state);
      std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
      state.velocity = std::move(velocities);
      if (outcome.residual <= handover) {
        return s;
      }
    }
  }
  return max_steps;
}

SettleOutcome relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                                       std::int64_t max_steps, double residual, State& state,
                                       const StepOptions& options, const RestartTest& stop) {
  SettleOutcome outcome;
  outcome.ran = true;
  outcome.residual = std::numeric_limits<double>::infinity();
  std::vector<Vec3> held_velocities;
  double previous_kinetic = 0.0;
  std::int64_t last_check = 0;
  for (std::int64_t s = 1; s <= max_steps; ++s) {
    step(model, dt, switches, state, options);
    outcome.steps = s;
    if (s % kViscousCheckInterval == 0) {
      stop_if_asked();
    }
    double kinetic = kinetic_measure(model, state);
    const bool peak = kinetic < previous_kinetic;
    if (peak || s - last_check >= kCheckInterval || s == max_steps) {
      if (!peak) {
        held_velocities = state.velocity;
      }
      compute_static_forces(model, switches, state);
      std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
      last_check = s;
      if (residual > 0.0 && outcome.residual <= residual) {
        break;
      }
      if (peak && stop && stop(state)) {
        outcome.stopped = true;
        break;
      }
      if (peak) {
        // Restart from rest at x: leapfrog starts from rest with v_{½} = ½ Δt a, so
        // v_{−½} = −½ Δt a. Zeroing v_{−½} instead would start every restart with a kick of
        // ½ Δt a, which feeds the stiffest modes at each of the frequent restarts near
        // convergence until they blow up (the paper's flag did, at 0.5 ms).
        outcome.restarts += 1;
        for (Index i = 0; i < model.node_count(); ++i) {
          state.velocity[i] = (-0.5 * dt * model.node_inv_mass[i]) * state.force[i];
        }
        kinetic = 0.0;
      } else {
        state.velocity = held_velocities;
      }
    }
    previous_kinetic = kinetic;
  }
  return outcome;
}

SettleOutcome creep_under_gravity(const Model& model, double dt, const ForceSwitches& quiet,
                                  State& settling) {
  StepOptions options;
  options.pins_hold_still = true;
  options.bars_as_springs = true;  // the model's own equilibrium, whatever its integrator
  for (Vec3& v : settling.velocity) {
    v.setZero();
  }
  start_leapfrog(model, dt, quiet, settling);
  SettleOutcome outcome;
  outcome.ran = true;
  outcome.max_steps = std::max<std::int64_t>(1, std::llround(model.settle.duration / dt));
  // The large motion, overdamped: a path without swings, so that where a limp structure folds or
  // which way a tie flops is decided by the structure, not by rounding (kinetic damping from the
  // start lets the fall swing chaotically, and 1e-12 m moved a tie 7 cm).
  const double damping = model.settle.damping.value_or(automatic_settle_damping(model));
  if (damping > 0.0) {
    outcome.viscous_steps =
        relax_viscously(model, dt, quiet, options, std::min(damping, 0.2 / dt), outcome.max_steps,
                        std::max(kViscousHandover, model.settle.residual), settling, outcome);
    outcome.steps = outcome.viscous_steps;
  }
  return outcome;
}

SettleOutcome relax_to_rest(const Model& model, double dt, const ForceSwitches& quiet,
                            State& settling, const RestartTest& stop) {
  SettleOutcome viscous = creep_under_gravity(model, dt, quiet, settling);
  if (viscous.steps >= viscous.max_steps) {
    return viscous;
  }
  // Then kinetic damping, which converges quickly near the equilibrium where viscous damping
  // crawls, handed over from rest as its restarts are (v_{−½} = −½ Δt a).
  if (viscous.steps > 0) {
    for (Index i = 0; i < model.node_count(); ++i) {
      settling.velocity[i] = (-0.5 * dt * model.node_inv_mass[i]) * settling.force[i];
    }
  }
  StepOptions options;
  options.pins_hold_still = true;
  options.bars_as_springs = true;  // the model's own equilibrium, whatever its integrator
  SettleOutcome outcome =
      relax_by_kinetic_damping(model, dt, quiet, viscous.max_steps - viscous.steps,
                               model.settle.residual, settling, options, stop);
  outcome.ran = true;
  outcome.viscous_steps = viscous.steps;
  outcome.steps += viscous.steps;
  outcome.max_steps = viscous.max_steps;
  return outcome;
}

}  // namespace dinam
