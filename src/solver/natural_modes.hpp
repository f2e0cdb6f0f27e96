#pragma once
// The natural modes of a structure about a static equilibrium: the lowest solutions of
// K φ = ω² M φ, K the stiffness as it is there (stiffness_matrix.hpp: every spring kind, with the
// geometric stiffness of the loads they carry, and the ground's penalty) and M the lumped masses
// of the free nodes, found by shift-invert Lanczos (Spectra) on M^{-½} K M^{-½} with a sparse
// factorisation. A mode's mass share in a direction is its effective modal mass there over the
// free mass: how much of the structure moves with it when the supports are shaken that way
// (the shares over all modes sum to 1).
//
// A mode is free (a motion nothing resists: a body sliding or turning) where its shape is a rigid
// motion the pins leave (rigid_motions.hpp) and its |ω²| is below both the loads' scale |g|/size
// and the eigensolver's round-off, 1e-14 of ω_max². A shape that bends anything is never free,
// however stiff the stiffest bar: the round-off of stiff bars pushed real sways under a threshold
// on |ω²| alone.
#include <vector>

#include "core/types.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

struct NaturalMode {
  double omega_squared = 0.0;      // 1/s², negative where the equilibrium is unstable
  double frequency = 0.0;          // Hz, ω / 2π (0 for a mode with ω² ≤ 0 and a free one)
  bool free = false;               // a rigid motion nothing resists: ω² is 0 within round-off
  Vec3 mass_share = Vec3::Zero();  // of the free mass, in x, y and z
  // (n_nodes) m per unit modal amplitude, φᵀ M φ = 1 kg; zero at pinned nodes. Its sign makes
  // its largest coordinate positive.
  std::vector<Vec3> shape;
};

// The `count` lowest modes about state.x (a static equilibrium: solver/settle.hpp), ascending,
// with the forces `switches` leaves on and the plastic sets the state holds. Fewer where the
// model has fewer free degrees of freedom. Throws RuntimeError where the eigensolver does not
// converge.
std::vector<NaturalMode> natural_modes(const Model& model, const State& state,
                                       const ForceSwitches& switches, int count);

}  // namespace dinam
