#include "solver/equilibrium.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/stop_request.hpp"
#include "dynamics/relaxation.hpp"
#include "model/model.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/potential.hpp"
#include "solver/stiffness_matrix.hpp"
#include "solver/sufficient_decrease.hpp"

namespace dinam {
namespace {

// Levenberg–Marquardt's added mass-proportional stiffness μ M, as a share of the mean K_ii/M_ii:
// the least added when K is singular, and the most before the search gives up (a direction so
// damped it moves nothing).
constexpr double kLeastShift = 1e-10;
constexpr double kMostShift = 1e6;
// Beyond this shift the stiffness as it is is far from definite (a structure buckling or folding):
// the elements are projected instead, and the shift starts again from zero.
constexpr double kProjectAbove = 0.1;
// Factorisations tried per iteration at most (each failed one raises the shift).
constexpr int kAttemptsPerIteration = 4;
// The stiffness as it is, still not positive definite with this much μ M (as a share of the mean
// K_ii/M_ii) added, has a negative eigenvalue, not a zero one rounded below zero.
constexpr double kUnstableShift = 1e-8;

using Vector = Eigen::VectorXd;

void move_free_nodes(const FreeDofs& dofs, const std::vector<Vec3>& from, const Vector& step,
                     double length, std::vector<Vec3>& to) {
  for (std::size_t i = 0; i < from.size(); ++i) {
    to[i] = dofs.first_dof[i] >= 0 ? Vec3(from[i] + length * step.segment<3>(dofs.first_dof[i]))
                                   : from[i];
  }
}

}  // namespace

EquilibriumOutcome find_equilibrium(const Model& model, const ForceSwitches& switches,
                                    const EquilibriumOptions& options, State& state) {
  EquilibriumOutcome outcome;
  const FreeDofs dofs = free_dofs(model);
  const std::vector<Vec3> origin = state.x;  // where gravity's energy is zero
  compute_static_forces(model, switches, state);
  std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
  const double start_residual = outcome.residual;
  if (dofs.count == 0 || outcome.residual <= options.residual) {
    outcome.converged = true;
    return outcome;
  }
  const Vector mass = free_masses(model, dofs);

  StiffnessAssembly assembly;
  PositiveDefiniteSolver factors;
  std::vector<Vec3> x = state.x;
  Vector force = free_part(dofs, state.force);
  Potential energy = potential_energy(model, state, switches, origin);
  Definiteness definiteness = Definiteness::kExact;
  SparseMatrix k;
  bool assembled = false;
  double shift = 0.0;        // μ, 1/s²: K + μ M is what is solved with
  double shift_scale = 0.0;  // the mean K_ii / M_ii at the start, 1/s²
  int attempts = 0;
  // Takes a more cautious step: more of μ M, and where even a large μ is needed to make the
  // stiffness as it is definite, its elements projected instead.
  auto back_off = [&] {
    shift = std::max(4.0 * shift, kLeastShift * shift_scale);
    if (definiteness == Definiteness::kExact && shift > kProjectAbove * shift_scale) {
      definiteness = Definiteness::kProjected;
      assembled = false;
      shift = 0.0;
    }
  };

  while (outcome.iterations < options.max_iterations &&
         attempts < kAttemptsPerIteration * options.max_iterations) {
    attempts += 1;
    stop_if_asked();
    if (!assembled) {
      state.x = x;
      k = assembly.assemble(model, state, switches, dofs, definiteness);
      assembled = true;
      if (shift_scale == 0.0) {
        shift_scale = std::max(k.diagonal().cwiseQuotient(mass).mean(), 1e-300);
      }
    }
    SparseMatrix shifted = k;
    if (shift > 0.0) {
      shifted.diagonal() += shift * mass;
    }
    if (!factors.factorize(shifted)) {
      // Not positive definite. Where the stiffness as it is needs more than a trace of μ M to be
      // (more than rounding or a mechanism's zero would), it has a negative eigenvalue: the
      // structure is unstable there, about to buckle or fold.
      if (definiteness == Definiteness::kExact && shift >= kUnstableShift * shift_scale) {
        outcome.unstable = true;
        if (options.stop_where_unstable) {
          outcome.failure = "the structure is unstable on the way (it buckles or folds)";
          break;
        }
      }
      back_off();
      if (shift > kMostShift * shift_scale) {
        outcome.failure =
            "the stiffness is singular: part of the structure can move without "
            "resisting (a mechanism)";
        break;
      }
      continue;
    }
    const Vector step = factors.solve(force);
    // The decrease the quadratic model of the energy promises: F·Δ − ½ ΔᵀKΔ (> 0 since K + μM
    // is positive definite).
    const double promised = force.dot(step) - 0.5 * step.dot(k * step);
    move_free_nodes(dofs, x, step, 1.0, state.x);
    const Potential trial = potential_energy(model, state, switches, origin);
    const double rounding = kEnergyRounding * std::max(energy.magnitude, trial.magnitude);
    // How much of the promised decrease the step delivered. Where rounding hides the energy's
    // change (near the equilibrium), a step that lowers the out-of-balance force counts as good.
    double delivered = 0.0;
    bool forces_at_trial = false;
    if (std::abs(trial.energy - energy.energy) <= rounding) {
      compute_static_forces(model, switches, state);
      forces_at_trial = true;
      delivered = free_part(dofs, state.force).squaredNorm() < force.squaredNorm() ? 1.0 : 0.0;
    } else {
      delivered = (energy.energy - trial.energy) / promised;
    }
    if (!(delivered > kSufficientDecrease)) {
      back_off();
      if (shift > kMostShift * shift_scale) {
        outcome.failure = "no step lowers the energy any further";
        break;
      }
      continue;
    }
    outcome.iterations += 1;
    x = state.x;
    energy = trial;
    assembled = false;
    if (!forces_at_trial) {
      compute_static_forces(model, switches, state);
    }
    force = free_part(dofs, state.force);
    std::tie(outcome.residual, outcome.worst_node) = relative_residual(model, state);
    if (outcome.residual <= options.residual) {
      outcome.converged = true;
      break;
    }
    // Trust the quadratic model more where it predicted well (towards Newton's own step, with
    // the stiffness as it is), less where it did not (Levenberg–Marquardt's rule).
    if (delivered > 0.75) {
      shift = shift > kLeastShift * shift_scale ? 0.25 * shift : 0.0;
      definiteness = Definiteness::kExact;
    } else if (delivered < 0.25) {
      shift = std::max(2.0 * shift, kLeastShift * shift_scale);
    }
  }
  if (!outcome.converged && outcome.failure.empty()) {
    outcome.failure = fmt::format(
        "it did not converge within {} Newton iterations (the out-of-balance force went from "
        "{:.2g} to {:.2g} of a node's weight)",
        options.max_iterations, start_residual, outcome.residual);
  }
  state.x = x;
  compute_static_forces(model, switches, state);
  return outcome;
}

}  // namespace dinam
