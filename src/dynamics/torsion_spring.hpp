#pragma once
// Torsion springs: one per bar i–j with reference neighbours i–a and j–b, on the dihedral angle
// φ between the planes (a, i, j) and (i, j, b): the twist of one end relative to the other,
// measured through the neighbours since nodes have no rotation. Elastoplastic in φ − φ0.
#include <limits>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

struct TorsionSpringResult {
  Vec3 force_a, force_i, force_j, force_b;  // N
  double energy;                            // J, ½ k (φ − φ0 − p)²
  double plastic_set = 0.0;                 // rad
  double dissipated = 0.0;                  // J
};

// With b1 = xi − xa, b2 = xj − xi, b3 = xb − xj, n1 = b1 × b2, n2 = b2 × b3 and φ as in
// core/geometry.hpp, the gradients are (Bekker's form, as in GROMACS's dihedral forces, with
// our sign of φ)
//   ∂φ/∂xa = −|b2| n1 / |n1|²,   ∂φ/∂xb = |b2| n2 / |n2|²,
//   ∂φ/∂xi = −(1 + b1·b2/|b2|²) ∂φ/∂xa + (b3·b2/|b2|²) ∂φ/∂xb,
//   ∂φ/∂xj = −(1 + b3·b2/|b2|²) ∂φ/∂xb + (b1·b2/|b2|²) ∂φ/∂xa,
// which sum to zero (a rigid translation does not twist); tests/dynamics/kernels_test.cpp checks
// them against finite differences of the energy.
// and the force is −T ∇φ with T = k wrap(φ − φ0 − p) flattened at ±Ty. If a reference bar
// swings into line with the axis (|n| → 0) the plane is lost and the force is left out for that
// configuration rather than made infinite.
TorsionSpringResult torsion_spring(const Vec3& xa, const Vec3& xi, const Vec3& xj, const Vec3& xb,
                                   double rest_angle, double stiffness, double plastic_set = 0.0,
                                   double yield = std::numeric_limits<double>::infinity());

void add_torsion_spring_forces(ForceContext& context);
double torsion_spring_energy(const Model& model, const State& state);

}  // namespace dinam
