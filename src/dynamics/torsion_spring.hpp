#pragma once
// Torsion springs: one per bar i–j with reference neighbours i–a and j–b, on the dihedral angle
// φ between the planes (a, i, j) and (i, j, b): the twist of one end relative to the other,
// measured through the neighbours since nodes have no rotation. Elastoplastic in φ − φ0.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

struct TorsionSpringResult {
  Vec3 force_a, force_i, force_j, force_b;  // N
  double energy;                            // J, w · ½ k (φ − φ0 − p)²
  double plastic_set = 0.0;                 // rad
  double dissipated = 0.0;                  // J
};

// A reference bar fixes a plane only while it is out of line with the bar: the twist φ is
// undefined when a reference is collinear with the bar, and its gradient grows as 1/sin there.
// So each end's reference is weighted by h(q), q = sin² of its angle with the bar: 1 while
// q ≥ kTorsionFullWeightSin2 (the sine of kMinReferenceSine, with which references are chosen),
// 0 below kTorsionNoWeightSin2 (sine 0.1, 5.7°), and a C¹ smoothstep between, so that
//   E = w · ½ k (φ − φ0 − p)²,   w = h(q_a) h(q_b),
// is C¹ for any motion, the spring is the paper's wherever its references are good, and its
// stiffness never exceeds k (the stability bound holds). The force is
//   f = −w T ∇φ − ½ k e² ∇w,   T = k e flattened at ±Ty/w (so that w T stays within ±Ty).
inline constexpr double kTorsionFullWeightSin2 = 0.2 * 0.2;
inline constexpr double kTorsionNoWeightSin2 = 0.1 * 0.1;

// h(q) and dh/dq.
struct ReferenceWeight {
  double weight;
  double slope;
};
[[gnu::always_inline]] inline ReferenceWeight reference_weight(double sin2) {
  constexpr double kPerBand = 1.0 / (kTorsionFullWeightSin2 - kTorsionNoWeightSin2);
  const double t = std::clamp((sin2 - kTorsionNoWeightSin2) * kPerBand, 0.0, 1.0);
  return {t * t * (3.0 - 2.0 * t), 6.0 * t * (1.0 - t) * kPerBand};
}

// q = sin² of the angle between u and v, q = 1 − (u·v)²/(|u|²|v|²), and its gradients
// ∂q/∂u = (2 u·v / (|u|²|v|²)) ((u·v/|u|²) u − v), ∂q/∂v likewise with u and v swapped.
struct Sin2Gradient {
  double sin2;
  Vec3 d_u, d_v;
};
[[gnu::always_inline]] inline Sin2Gradient sin2_between(const Vec3& u, const Vec3& v) {
  const double uu = dot3(u, u);
  const double vv = dot3(v, v);
  const double uv = dot3(u, v);
  const double inverse = 1.0 / (uu * vv > 0.0 ? uu * vv : 1.0);  // the one division
  const double scale = 2.0 * uv * inverse;
  return {1.0 - uv * uv * inverse, scale * ((uv * vv * inverse) * u - v),
          scale * ((uv * uu * inverse) * v - u)};
}

// With b1 = xi − xa, b2 = xj − xi, b3 = xb − xj, n1 = b1 × b2, n2 = b2 × b3 and φ as in
// core/geometry.hpp, the gradients of φ are (Bekker's form, as in GROMACS's dihedral forces, with
// our sign of φ)
//   ∂φ/∂xa = −|b2| n1 / |n1|²,   ∂φ/∂xb = |b2| n2 / |n2|²,
//   ∂φ/∂xi = −(1 + b1·b2/|b2|²) ∂φ/∂xa + (b3·b2/|b2|²) ∂φ/∂xb,
//   ∂φ/∂xj = −(1 + b3·b2/|b2|²) ∂φ/∂xb + (b1·b2/|b2|²) ∂φ/∂xa,
// which sum to zero (a rigid translation does not twist); tests/dynamics/kernels_test.cpp checks
// the forces against finite differences of the energy, near-collinear references included.
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

  // The references' weights and the gradient of w = h_a h_b.
  const Sin2Gradient qa = sin2_between(b1, b2);
  const Sin2Gradient qb = sin2_between(b3, b2);
  const ReferenceWeight ha = reference_weight(qa.sin2);
  const ReferenceWeight hb = reference_weight(qb.sin2);
  const double weight = ha.weight * hb.weight;
  const double wa = ha.slope * hb.weight;  // ∂w/∂q_a
  const double wb = ha.weight * hb.slope;  // ∂w/∂q_b
  // b1 = xi − xa, b2 = xj − xi, b3 = xb − xj.
  const Vec3 dw_a = -wa * qa.d_u;
  const Vec3 dw_i = wa * (qa.d_u - qa.d_v) - wb * qb.d_v;
  const Vec3 dw_j = wa * qa.d_v + wb * (qb.d_v - qb.d_u);
  const Vec3 dw_b = wb * qb.d_u;

  const double angle = fast_atan2(b2_norm * dot3(b1, n2), dot3(n1, n2));
  // The plastic set accumulates unwrapped; only the elastic part is taken the short way round.
  const double deformation = plastic_set + wrap_angle(angle - rest_angle - plastic_set);
  const double weighted_yield =
      weight > 0.0 ? yield / weight : std::numeric_limits<double>::infinity();
  const ElastoplasticResult r = elastoplastic(deformation, plastic_set, stiffness, weighted_yield);
  const double n1_squared = dot3(n1, n1);
  const double n2_squared = dot3(n2, n2);
  // Where a weight is zero the planes may be undefined; the guards keep the arithmetic finite.
  const bool has_planes = weight > 0.0 && b2_norm > 0.0 && n1_squared > 0.0 && n2_squared > 0.0;
  const double safe_b2_squared = has_planes ? b2_squared : 1.0;
  const double moment = has_planes ? weight * r.force : 0.0;
  const Vec3 grad_a = -(b2_norm / (has_planes ? n1_squared : 1.0)) * n1;
  const Vec3 grad_b = (b2_norm / (has_planes ? n2_squared : 1.0)) * n2;
  const double s1 = dot3(b1, b2) / safe_b2_squared;
  const double s3 = dot3(b3, b2) / safe_b2_squared;
  const Vec3 grad_i = -(1.0 + s1) * grad_a + s3 * grad_b;
  const Vec3 grad_j = -(1.0 + s3) * grad_b + s1 * grad_a;
  const double elastic_energy = r.energy;  // ½ k e², before weighting
  return {-moment * grad_a - elastic_energy * dw_a,
          -moment * grad_i - elastic_energy * dw_i,
          -moment * grad_j - elastic_energy * dw_j,
          -moment * grad_b - elastic_energy * dw_b,
          weight * r.energy,
          r.plastic_set,
          weight * r.dissipated};
}

void add_torsion_spring_forces(ForceContext& context);
double torsion_spring_energy(const Model& model, const State& state);

}  // namespace dinam
