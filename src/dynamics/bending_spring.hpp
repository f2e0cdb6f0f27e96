#pragma once
// Bending springs: a rotational spring at node c between the bars c–a and c–b, on the angle θ
// between them, elastoplastic in θ − θ0.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/spring_kind.hpp"
#include "dynamics/stiffness.hpp"

namespace dinam {

// Below this sine of θ, |n| / (|e1| |e2|), the in-plane directions are lost in rounding.
inline constexpr double kBendingMinSine = 1e-9;
// The widest deflection from straight (rad) over which a bent rest's cone point is rounded.
inline constexpr double kBendingStraightCap = 0.05;

template <class T>
struct BendingSpringResult {
  Eigen::Matrix<T, 3, 1> force_a, force_c, force_b;  // N
  T energy;                                          // J, ½ k (θ − θ0 − p)²
  T plastic_set = 0.0;                               // rad
  double dissipated = 0.0;                           // J
};

// With e1 = xa − xc, e2 = xb − xc and n = e1 × e2, θ = atan2(|n|, e1·e2) and
//   ∂θ/∂xa = (e1 × n) / (|e1|² |n|),  ∂θ/∂xb = (n × e2) / (|e2|² |n|),
//   ∂θ/∂xc = −(∂θ/∂xa + ∂θ/∂xb),
// each perpendicular to its bar in the plane of the bars, over the bar's length; the force is
// −M ∇θ with M = k (θ − θ0 − p) flattened at ±My. One square root and two divisions per spring:
// the three quotients the spring needs (the arctangent's reduction, the cap's 1/w and the
// force's 1/(|n| |e1|² |e2|²)) come from one reciprocal of their denominators' product, and the
// arctangent keeps one of its own; a spring that can yield takes a third. When the bars are
// (nearly) straight the plane is undefined; then M → 0 for a straight rest angle (the force fades
// smoothly), and otherwise the force is left out for that one configuration (bounded, no NaN)
// rather than given a random direction. A bar of zero length leaves the spring at rest. No
// branches: the spring loop vectorises (spring_block.hpp). T is double, or Dual for the forces'
// derivatives (bending_spring_hessian).
template <class T>
[[gnu::always_inline]] inline BendingSpringResult<T> bending_spring(
    const Eigen::Matrix<T, 3, 1>& xa, const Eigen::Matrix<T, 3, 1>& xc,
    const Eigen::Matrix<T, 3, 1>& xb, double rest_angle, double stiffness, double plastic_set = 0.0,
    double yield = std::numeric_limits<double>::infinity()) {
  using V = Eigen::Matrix<T, 3, 1>;
  using std::sqrt;
  constexpr double kMinSine = kBendingMinSine;
  constexpr double kStraightCap = kBendingStraightCap;
  const V e1 = xa - xc;
  const V e2 = xb - xc;
  const T l1_squared = dot3(e1, e1);
  const T l2_squared = dot3(e2, e2);
  const T lengths_squared = l1_squared * l2_squared;
  const V n = cross3(e1, e2);
  const T n_squared = dot3(n, n);
  const T n_norm = sqrt(n_squared);
  const bool has_plane = n_squared > kMinSine * kMinSine * lengths_squared;
  // Near straight, a spring whose rest is bent by ψ0 > 0 would have a cone point (see above);
  // within ψ < w = min(ψ0, kStraightCap) its energy is the even quartic a + b ψ² + c ψ⁴ that meets
  // ½ k (ψ0 − ψ)² at w with the same value, slope and curvature. No plastic flow there: the
  // quartic's moment is at most the line's, and is held to the yield moment.
  const double rest_deflection = std::numbers::pi - rest_angle - plastic_set;  // ψ0
  const double width = rest_deflection > 0.0 ? std::min(rest_deflection, kStraightCap) : 1.0;
  // The reciprocal of the three denominators' product, and each quotient from it.
  const Atan2Reduction<T> reduced = atan2_reduce(n_norm, dot3(e1, e2));
  const T force_denominator = has_plane ? T(n_norm * lengths_squared) : T(1.0);
  const T reciprocal = 1.0 / (reduced.bottom * width * force_denominator);
  const T measured = atan2_finish(reduced, reduced.top * (width * force_denominator * reciprocal));
  const T inverse_width = reduced.bottom * force_denominator * reciprocal;
  const T inverse_force_denominator = reduced.bottom * width * reciprocal;

  const T angle = lengths_squared > 0.0 ? measured : T(rest_angle + plastic_set);
  const ElastoplasticResult<T> r =
      elastoplastic(T(angle - rest_angle), plastic_set, stiffness, yield);
  const T deflection = std::numbers::pi - angle;  // ψ
  const bool capped = rest_deflection > 0.0 && deflection < width;
  const T ratio = rest_deflection * inverse_width;                              // ψ0 / w ≥ 1
  const T quartic = 0.125 * stiffness * ratio * inverse_width * inverse_width;  // k ψ0 / 8w³
  const T quadratic = stiffness * (0.5 - 0.75 * ratio);                         // b
  const T psi2 = deflection * deflection;
  const T cap_moment = std::clamp<T>(-(2.0 * quadratic + 4.0 * quartic * psi2) * deflection, -yield,
                                     yield);  // dE/dθ
  const T cap_energy = 0.5 * stiffness * (rest_deflection - width) * (rest_deflection - width) +
                       quadratic * (psi2 - width * width) +
                       quartic * (psi2 * psi2 - width * width * width * width);
  const T moment = capped ? cap_moment : r.force;
  const T scale =
      has_plane ? T(moment * inverse_force_denominator) : T(0.0);  // M / (|e1|² |e2|² |n|)
  BendingSpringResult<T> result;
  result.force_a = (-scale * l2_squared) * cross3(e1, n);
  result.force_b = (-scale * l1_squared) * cross3(n, e2);
  result.force_c = -(result.force_a + result.force_b);
  result.energy = capped ? cap_energy : r.energy;
  result.plastic_set = capped ? T(plastic_set) : r.plastic_set;
  result.dissipated = capped ? 0.0 : r.dissipated;
  return result;
}

// The spring's stiffness matrix at (xa, xc, xb) (stiffness.hpp): the Jacobian of the kernel's
// forces, except where the bars are in line. There the kernel's forces vanish and its plane is
// undefined, but the stiffness is not zero: the energy is even in the deflection ψ about straight,
// E ≈ E(0) + ½ c ψ², ψ = |P δe1 / |e1| + P δe2 / |e2||, P the projection across the line, so
// K = c Jᵀ J with J = [P/|e1|, −P (1/|e1| + 1/|e2|), P/|e2|]: c = k for a straight rest, and 2b,
// the rounded cap's curvature, for a bent one (negative: straight is unstable for it).
LocalStiffness<3> bending_spring_stiffness(const std::array<Vec3, 3>& at, double rest_angle,
                                           double stiffness, double plastic_set, double yield);

void add_bending_spring_forces(ForceContext& context);
double bending_spring_energy(const Model& model, const State& state, SpringEnergy which);
void add_bending_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink);

// The entry of spring_kinds.hpp.
extern const SpringKind kBendingSprings;

}  // namespace dinam
