#pragma once
// The stiffness matrix of the whole model, K = −∂F/∂x over its free degrees of freedom, assembled
// from each force kind's element matrices (dynamics/stiffness.hpp). Newton's method solves with it
// (equilibrium.hpp); the natural modes are its eigenvectors against the masses (natural_modes.hpp).
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/free_dofs.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

using SparseMatrix = Eigen::SparseMatrix<double>;

// kExact: the stiffness as it is, which is indefinite where the structure is unstable (a bar in
// compression, a bent spring near its straight). kProjected: each element's matrix made positive
// semi-definite first (its negative eigenvalues set to zero), so that the sum is too and a Newton
// step with it goes downhill on the energy, wherever it starts.
enum class Definiteness { kExact, kProjected };

// Assembles K at state.x (plastic sets and broken springs as the state holds them) from every
// spring kind `switches` leaves on, the ground's normal penalty and that of the pairs of objects
// touching at the state's last force evaluation; gravity and fields are constant and add nothing.
// Every free node's diagonal block is in the pattern, zero where nothing acts, so the pattern is
// the springs' alone whatever touches the ground: a solver can analyse it once. The pattern is
// found first, from the blocks the elements hand over, and the values are then added into it;
// from the second call on, into the last call's pattern (a fifth of a triplet assembly's time on
// a 2 000-node wire), found afresh only where a block falls outside it (a pair of objects that
// was not touching).
class StiffnessAssembly {
 public:
  const SparseMatrix& assemble(const Model& model, const State& state,
                               const ForceSwitches& switches, const FreeDofs& dofs,
                               Definiteness definiteness);

 private:
  std::vector<std::uint64_t> blocks_;  // a new pattern's blocks, while it is found
  SparseMatrix matrix_;
};

// K's rotation-invariant part over the free nodes: each element's matrix made positive
// semi-definite, then each of its 3 × 3 blocks between free nodes a and b reduced to its trace,
// added as the triplet (a, b) of a matrix over the free nodes (node i's index first_dof[i] / 3).
// A bar's k n nᵀ gives k whichever way it points (projective dynamics' spring, k I); a spring of
// an angle's k g gᵀ gives the Gram matrix k g_a·g_b of its gradient's blocks. The sum is positive
// semi-definite, and the same after any rotation of the structure: the constant matrix of the
// solver for stiff threads (solver/stiff_threads.hpp).
void add_block_traces(const Model& model, const State& state, const ForceSwitches& switches,
                      const FreeDofs& dofs, std::vector<Eigen::Triplet<double>>& traces);

}  // namespace dinam
