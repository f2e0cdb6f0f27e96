#include "dynamics/settle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/error.hpp"
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
    sum += model.node_mass[i] * state.v_half[i].squaredNorm();
  }
  return sum;
}

// The static forces at the present positions (velocities zero: no damping or drag) into
// state.force, leaving plastic sets and contact anchors as they are.
void compute_static_forces(const Model& model, const ForceSwitches& switches, State& state) {
  for (Vec3& v : state.v_half) {
    v.setZero();
  }
  compute_forces(model, switches, state, false);
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

double automatic_settle_damping(const Model& model) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      low = low.cwiseMin(model.node_initial_x[i]);
      high = high.cwiseMax(model.node_initial_x[i]);
    }
  }
  const double size = low.x() <= high.x() ? (high - low).norm() : 0.0;
  const double g = model.gravity.norm() > 0.0 ? model.gravity.norm() : kStandardGravity;
  return size > 0.0 ? 8.0 * std::sqrt(g / size) : 0.0;
}

std::int64_t relax_viscously(const Model& model, double dt, const ForceSwitches& switches,
                             double damping, std::int64_t max_steps, double handover, State& state,
                             SettleOutcome& outcome) {
  Model damped = model;
  damped.global_damping = damping;
  for (std::int64_t s = 1; s <= max_steps; ++s) {
    step(damped, dt, switches, state);
    if (s % kViscousCheckInterval == 0 || s == max_steps) {
      std::vector<Vec3> velocities = state.v_half;
      compute_static_forces(model, switches, state);
      std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
      state.v_half = std::move(velocities);
      if (outcome.residual <= handover) {
        return s;
      }
    }
  }
  return max_steps;
}

SettleOutcome relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                                       std::int64_t max_steps, double residual, State& state) {
  SettleOutcome outcome;
  outcome.ran = true;
  outcome.residual = std::numeric_limits<double>::infinity();
  std::vector<Vec3> held_velocities;
  double previous_kinetic = 0.0;
  std::int64_t last_check = 0;
  for (std::int64_t s = 1; s <= max_steps; ++s) {
    step(model, dt, switches, state);
    outcome.steps = s;
    double kinetic = kinetic_measure(model, state);
    const bool peak = kinetic < previous_kinetic;
    if (peak || s - last_check >= kCheckInterval || s == max_steps) {
      if (!peak) {
        held_velocities = state.v_half;
      }
      compute_static_forces(model, switches, state);
      std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
      last_check = s;
      if (residual > 0.0 && outcome.residual <= residual) {
        break;
      }
      if (peak) {
        // Restart from rest at x: leapfrog starts from rest with v_{½} = ½ Δt a, so
        // v_{−½} = −½ Δt a. Zeroing v_{−½} instead would start every restart with a kick of
        // ½ Δt a, which feeds the stiffest modes at each of the frequent restarts near
        // convergence until they blow up (the paper's flag did, at 0.5 ms).
        outcome.restarts += 1;
        for (Index i = 0; i < model.node_count(); ++i) {
          state.v_half[i] = (-0.5 * dt * model.node_inv_mass[i]) * state.force[i];
        }
        kinetic = 0.0;
      } else {
        state.v_half = held_velocities;
      }
    }
    previous_kinetic = kinetic;
  }
  return outcome;
}

void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state) {
  if (!model.settle.enabled) {
    return;
  }
  // The same structure at rest with nothing but gravity and the ground acting. A copy is made once
  // per run, which is cheap beside the steps that follow.
  Model quiet = model;
  quiet.fields.clear();
  quiet.wind.faces.clear();
  quiet.wind.bars.clear();
  quiet.pin_motions.clear();  // supports hold still where they start
  for (Vec3& v : quiet.node_initial_v) {
    v.setZero();
  }
  quiet.settle = {};
  quiet.node_initial_x = state.x;

  State settling = initial_state(quiet, dt, switches, false);
  const auto max_steps = std::max<std::int64_t>(1, std::llround(model.settle.duration / dt));
  // First the large motion, overdamped: a path without swings, so that where a limp structure
  // folds or which way a tie flops is decided by the structure, not by rounding (kinetic damping
  // from the start lets the fall swing chaotically, and 1e-12 m moved a tie 7 cm). Then kinetic
  // damping, which converges quickly near the equilibrium where viscous damping crawls.
  const double damping = model.settle.damping.value_or(automatic_settle_damping(model));
  SettleOutcome viscous;
  const std::int64_t viscous_steps =
      damping > 0.0
          ? relax_viscously(quiet, dt, switches, std::min(damping, 0.2 / dt), max_steps,
                            std::max(kViscousHandover, model.settle.residual), settling, viscous)
          : 0;
  if (viscous_steps > 0) {
    // Hand over from rest, as kinetic damping's restarts do (v_{−½} = −½ Δt a).
    for (Index i = 0; i < quiet.node_count(); ++i) {
      settling.v_half[i] = (-0.5 * dt * quiet.node_inv_mass[i]) * settling.force[i];
    }
  }
  state.settled = viscous_steps < max_steps
                      ? relax_by_kinetic_damping(quiet, dt, switches, max_steps - viscous_steps,
                                                 model.settle.residual, settling)
                      : viscous;
  state.settled.viscous_steps = viscous_steps;
  state.settled.steps += viscous_steps;
  const SettleOutcome& outcome = state.settled;
  if (!(outcome.residual <= model.settle.residual)) {
    const Index node = outcome.worst_node;
    const ModelObject& object = model.objects[model.node_object[node]];
    throw_user_error(
        model.settle.loc,
        "the settling phase did not come to rest within its {:g} s ({} steps): the largest "
        "out-of-balance force is still {:.3g} of a node's weight (node {} of object '{}'), above "
        "'settle.residual' {:g}. Give 'settle.duration' more time or 'settle.residual' a larger "
        "value; if it never settles, part of the structure can move without resisting (a "
        "mechanism, a node with too few bars) or the time step is too long for it",
        model.settle.duration, max_steps, outcome.residual, node - object.first_node, object.name,
        model.settle.residual);
  }
  state.x = std::move(settling.x);
  state.bar_plastic_set = std::move(settling.bar_plastic_set);
  state.bend_plastic_set = std::move(settling.bend_plastic_set);
  state.torsion_plastic_set = std::move(settling.torsion_plastic_set);
  state.clamp_plastic_set = std::move(settling.clamp_plastic_set);
  state.contact_anchor = std::move(settling.contact_anchor);
  state.contact_touching = std::move(settling.contact_touching);
  state.contact_sliding = std::move(settling.contact_sliding);
  state.bar_broken = std::move(settling.bar_broken);  // what broke under its own weight
  state.bend_broken = std::move(settling.bend_broken);
  state.torsion_broken = std::move(settling.torsion_broken);
  state.clamp_broken = std::move(settling.clamp_broken);
  state.face_broken = std::move(settling.face_broken);
  state.broken_bars = std::move(settling.broken_bars);
}

}  // namespace dinam
