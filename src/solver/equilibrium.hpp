#pragma once
// Static equilibrium by Newton's method on the potential energy (potential.hpp): from a start, each
// iteration solves (K + μM) Δx = F with the sparse stiffness (stiffness_matrix.hpp) and the
// lumped masses, and takes the step where the energy falls by enough of what the quadratic model
// promised, until the out-of-balance force on every free node is a small share of its weight.
// μ is Levenberg–Marquardt's: zero while the model predicts well (Newton's own step, which
// converges quadratically near a stable equilibrium), raised where a step failed or the stiffness
// is not positive definite (a bar in compression, a structure buckling), which turns the step
// towards an implicit step of overdamped motion. Where the stiffness as it is would need a large
// μ, its elements are projected to positive semi-definite instead. The equilibrium found does not
// depend on the masses (μ only steers the way there) or on any time step.
#include <string>

#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

struct EquilibriumOptions {
  double residual = 1e-6;    // the largest out-of-balance force allowed, of a free node's weight
  int max_iterations = 200;  // Newton iterations
  // Give up as soon as the stiffness is found indefinite: which way an unstable structure goes
  // depends on the path, which Newton's steps do not follow.
  bool stop_where_unstable = false;
};

struct EquilibriumOutcome {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // largest out-of-balance force on a free node / that node's weight
  Index worst_node = -1;
  // The stiffness was indefinite at some iterate: the structure passed through an unstable shape.
  bool unstable = false;
  std::string failure;  // why it did not converge, for the user; empty when it did
};

// From state.x (velocities ignored, histories held: plastic sets, broken springs), with the forces
// `switches` leaves on (gravity, springs, the ground's normal penalty; fields and wind should be
// off: they are not potentials), pinned nodes where they are. Leaves the positions reached in
// state.x and the static forces there in state.force; velocities zero.
EquilibriumOutcome find_equilibrium(const Model& model, const ForceSwitches& switches,
                                    const EquilibriumOptions& options, State& state);

}  // namespace dinam
