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
#include "dynamics/spring_kind.hpp"

namespace dinam {

template <class T>
struct TorsionSpringResult {
  Eigen::Matrix<T, 3, 1> force_a, force_i, force_j, force_b;  // N
  T energy;                                                   // J, w · ½ k (φ − φ0 − p)²
  T plastic_set = 0.0;                                        // rad
  double dissipated = 0.0;                                    // J
};

// A reference bar fixes a plane only while it is out of line with the bar: the twist φ is
// undefined when a reference is collinear with the bar, and its gradient grows as 1/sin there
// (|∂φ/∂x_a| = 1/(|b1| sin θa)). So the energy is weighted by the sines squared of both
// references' angles with the bar, q = sin²θ:
//   E = w · ½ k (φ − φ0 − p)²,   w = q_a q_b,
// with k the model's torsion_stiffness, G J / (L0 q_a0 q_b0), so that the spring is the paper's
// G J / L0 at rest and under any twist about the bar (which leaves q_a and q_b as they are). The
// weight cancels the 1/sin² of the gradient: the energy is smooth for any motion but a reference
// exactly in line, where it is still continuously differentiable with zero gradient (the spring
// vanishes as the reference swings into line), and the spring's stiffness against moving a node,
// w k |∂φ/∂x_a|² = k_0 q_b / (q_b0 q_a0 |b1|²) with k_0 = G J / L0, never passes its rest value
// k_0 / (q_a0 |b1|²) by more than the factor 1/q_b0 (1 or 2 for the references of a grid, which
// are chosen as perpendicular as the mesh allows); the fixed-band fade this replaced let it grow
// as 1/q_a, 25-fold before the fade began. The force is
//   f = −w T ∇φ − ½ k e² ∇w,   T = k e flattened at ±Ty/w (so that w T stays within ±Ty).

// q = sin² of the angle between u and v, q = |u × v|²/(|u|²|v|²) = 1 − (u·v)²/(|u|²|v|²)
// (taken from the cross product, exact near collinear where 1 − cos² is all rounding), and its
// gradients ∂q/∂u = (2 u·v / (|u|²|v|²)) ((u·v/|u|²) u − v), ∂q/∂v likewise with u and v
// swapped, given |u × v|² and inverse = 1 / (|u|²|v|²) (the caller's, from a shared reciprocal).
template <class T>
struct Sin2Gradient {
  T sin2;
  Eigen::Matrix<T, 3, 1> d_u, d_v;
};
template <class T>
[[gnu::always_inline]] inline Sin2Gradient<T> sin2_between(const Eigen::Matrix<T, 3, 1>& u,
                                                           const Eigen::Matrix<T, 3, 1>& v,
                                                           const T& uu, const T& vv,
                                                           const T& cross_squared,
                                                           const T& inverse) {
  const T uv = dot3(u, v);
  const T scale = 2.0 * uv * inverse;
  return {cross_squared * inverse, scale * ((uv * vv * inverse) * u - v),
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
// Six quotients (the weights' 1/(|b1|²|b2|²) and 1/(|b3|²|b2|²), 1/|b2|², 1/|n1|², 1/|n2|² and
// the arctangent's reduction) come from two reciprocals of products (one would underflow for a
// nearly collinear reference on a short bar), so a spring takes three divisions and a square
// root; one that can yield, two divisions more.
// No branches: the spring loop vectorises (spring_block.hpp), provided the kernel is inlined into
// it, which the compiler would not do by itself for one this long.
template <class T>
[[gnu::always_inline]] inline TorsionSpringResult<T> torsion_spring(
    const Eigen::Matrix<T, 3, 1>& xa, const Eigen::Matrix<T, 3, 1>& xi,
    const Eigen::Matrix<T, 3, 1>& xj, const Eigen::Matrix<T, 3, 1>& xb, double rest_angle,
    double stiffness, double plastic_set = 0.0,
    double yield = std::numeric_limits<double>::infinity()) {
  using V = Eigen::Matrix<T, 3, 1>;
  using std::sqrt;
  const V b1 = xi - xa;
  const V b2 = xj - xi;
  const V b3 = xb - xj;
  const V n1 = cross3(b1, b2);
  const V n2 = cross3(b2, b3);
  const T b1_squared = dot3(b1, b1);
  const T b2_squared = dot3(b2, b2);
  const T b3_squared = dot3(b3, b3);
  const T b2_norm = sqrt(b2_squared);
  const T n1_squared = dot3(n1, n1);
  const T n2_squared = dot3(n2, n2);

  // The reciprocals. Where a product is 0 (a bar of no length, a reference in line) its factor
  // stands in as 1: the weight or the guards below make what it feeds irrelevant there.
  const T a_product = b1_squared * b2_squared;  // |b1|²|b2|²
  const T b_product = b3_squared * b2_squared;  // |b3|²|b2|²
  const T safe_a = a_product > 0.0 ? a_product : 1.0;
  const T safe_b = b_product > 0.0 ? b_product : 1.0;
  const T safe_b2 = b2_squared > 0.0 ? b2_squared : 1.0;
  const T lengths_reciprocal = 1.0 / (safe_a * safe_b * safe_b2);
  const Atan2Reduction<T> reduced = atan2_reduce(b2_norm * dot3(b1, n2), dot3(n1, n2));
  const T safe_n1 = n1_squared > 0.0 ? n1_squared : 1.0;
  const T safe_n2 = n2_squared > 0.0 ? n2_squared : 1.0;
  const T planes_reciprocal = 1.0 / (safe_n1 * safe_n2 * reduced.bottom);

  // The weight w = q_a q_b and its gradient.
  const Sin2Gradient<T> qa = sin2_between(b1, b2, b1_squared, b2_squared, n1_squared,
                                          safe_b * safe_b2 * lengths_reciprocal);
  const Sin2Gradient<T> qb = sin2_between(b3, b2, b3_squared, b2_squared, n2_squared,
                                          safe_a * safe_b2 * lengths_reciprocal);
  const T weight = qa.sin2 * qb.sin2;
  const T wa = qb.sin2;  // ∂w/∂q_a
  const T wb = qa.sin2;  // ∂w/∂q_b
  // b1 = xi − xa, b2 = xj − xi, b3 = xb − xj.
  const V dw_a = -wa * qa.d_u;
  const V dw_i = wa * (qa.d_u - qa.d_v) - wb * qb.d_v;
  const V dw_j = wa * qa.d_v + wb * (qb.d_v - qb.d_u);
  const V dw_b = wb * qb.d_u;

  const T angle = atan2_finish(reduced, reduced.top * (safe_n1 * safe_n2 * planes_reciprocal));
  // The plastic set accumulates unwrapped; only the elastic part is taken the short way round.
  const T deformation = plastic_set + wrap_angle(angle - rest_angle - plastic_set);
  // (An elastic spring's yield is the constant ∞, which the compiler then carries through.)
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const T weighted_yield =
      yield == kInfinity ? kInfinity : (weight > 0.0 ? yield / weight : kInfinity);
  const ElastoplasticResult<T> r =
      elastoplastic(deformation, plastic_set, stiffness, weighted_yield);
  // Where a weight is zero the planes may be undefined; the guards keep the arithmetic finite.
  const bool has_planes = weight > 0.0 && b2_norm > 0.0 && n1_squared > 0.0 && n2_squared > 0.0;
  const T inverse_b2_squared = safe_a * safe_b * lengths_reciprocal;
  const T moment = has_planes ? weight * r.force : 0.0;
  const V grad_a = -(b2_norm * safe_n2 * reduced.bottom * planes_reciprocal) * n1;
  const V grad_b = (b2_norm * safe_n1 * reduced.bottom * planes_reciprocal) * n2;
  const T s1 = dot3(b1, b2) * inverse_b2_squared;
  const T s3 = dot3(b3, b2) * inverse_b2_squared;
  const V grad_i = -(1.0 + s1) * grad_a + s3 * grad_b;
  const V grad_j = -(1.0 + s3) * grad_b + s1 * grad_a;
  const T elastic_energy = r.energy;  // ½ k e², before weighting
  return {-moment * grad_a - elastic_energy * dw_a,
          -moment * grad_i - elastic_energy * dw_i,
          -moment * grad_j - elastic_energy * dw_j,
          -moment * grad_b - elastic_energy * dw_b,
          weight * r.energy,
          r.plastic_set,
          value_of(weight) * r.dissipated};
}

void add_torsion_spring_forces(ForceContext& context);
double torsion_spring_energy(const Model& model, const State& state, SpringEnergy which);
void add_torsion_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink);

// The entry of spring_kinds.hpp.
extern const SpringKind kTorsionSprings;

}  // namespace dinam
