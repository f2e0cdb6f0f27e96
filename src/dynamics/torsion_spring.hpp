#pragma once
// Torsion springs: one per bar i–j with reference neighbours i–a and j–b, on the dihedral angle
// φ between the planes (a, i, j) and (i, j, b): the twist of one end relative to the other,
// measured through the neighbours since nodes have no rotation. Elastoplastic in φ − φ0.
#include <cmath>
#include <limits>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/elastoplastic.hpp"
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
// No branches: the spring loop vectorises (spring_block.hpp), provided the kernel is inlined into
// it, which the compiler would not do by itself for one this long.
[[gnu::always_inline]] inline TorsionSpringResult torsion_spring(
    const Vec3& xa, const Vec3& xi, const Vec3& xj, const Vec3& xb, double rest_angle,
    double stiffness, double plastic_set = 0.0,
    double yield = std::numeric_limits<double>::infinity()) {
  const Vec3 b1 = xi - xa;
  const Vec3 b2 = xj - xi;
  const Vec3 b3 = xb - xj;
  const Vec3 n1 = cross3(b1, b2);
  const Vec3 n2 = cross3(b2, b3);
  const double b2_squared = dot3(b2, b2);
  const double b2_norm = std::sqrt(b2_squared);
  const double angle = fast_atan2(b2_norm * dot3(b1, n2), dot3(n1, n2));
  // The plastic set accumulates unwrapped; only the elastic part is taken the short way round.
  const double deformation = plastic_set + wrap_angle(angle - rest_angle - plastic_set);
  const ElastoplasticResult r = elastoplastic(deformation, plastic_set, stiffness, yield);
  const double n1_squared = dot3(n1, n1);
  const double n2_squared = dot3(n2, n2);
  // Relative to the bar's own scale, below this a reference plane is numerically undefined.
  const double tiny = 1e-18 * b2_squared * (dot3(b1, b1) + dot3(b3, b3));
  const bool has_planes = b2_norm > 0.0 && n1_squared > tiny && n2_squared > tiny;
  const double safe_b2_squared = has_planes ? b2_squared : 1.0;
  const double moment = has_planes ? r.force : 0.0;
  const Vec3 grad_a = -(b2_norm / (has_planes ? n1_squared : 1.0)) * n1;
  const Vec3 grad_b = (b2_norm / (has_planes ? n2_squared : 1.0)) * n2;
  const double s1 = dot3(b1, b2) / safe_b2_squared;
  const double s3 = dot3(b3, b2) / safe_b2_squared;
  const Vec3 grad_i = -(1.0 + s1) * grad_a + s3 * grad_b;
  const Vec3 grad_j = -(1.0 + s3) * grad_b + s1 * grad_a;
  return {-moment * grad_a, -moment * grad_i, -moment * grad_j, -moment * grad_b,
          r.energy,         r.plastic_set,    r.dissipated};
}

void add_torsion_spring_forces(ForceContext& context);
double torsion_spring_energy(const Model& model, const State& state);

}  // namespace dinam
