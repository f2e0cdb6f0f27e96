#pragma once
// Axial springs and dampers: one per bar, k = EA / L0, elastoplastic in the extension, with a
// viscous damper on the relative axial velocity of the two ends.
#include <cmath>
#include <limits>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/spring_kind.hpp"

namespace dinam {

template <class T>
struct AxialSpringResult {
  Eigen::Matrix<T, 3, 1> force_on_n0;  // N; the force on n1 is its negative
  T energy;                            // J, ½ k (L − L0 − p)²
  T plastic_set = 0.0;
  double dissipated = 0.0;
};

// The kernel over one bar's two nodes. With d = x1 − x0, L = |d|, n = d / L and the axial force
// N = k (L − L0 − p) (tension positive, flattened at ±Ny): f0 = N n, f1 = −f0.
// A bar of zero current length has no direction and gives no force.
// No branches: the spring loop vectorises (spring_block.hpp). T is double, or Dual for the
// forces' derivatives (axial_spring_hessian).
template <class T>
[[gnu::always_inline]] inline AxialSpringResult<T> axial_spring(
    const Eigen::Matrix<T, 3, 1>& x0, const Eigen::Matrix<T, 3, 1>& x1, double rest_length,
    double stiffness, double plastic_set = 0.0,
    double yield = std::numeric_limits<double>::infinity()) {
  using std::sqrt;
  const Eigen::Matrix<T, 3, 1> d = x1 - x0;
  const T length = sqrt(dot3(d, d));
  const ElastoplasticResult<T> r =
      elastoplastic(T(length - rest_length), plastic_set, stiffness, yield);
  const T quotient = r.force / (length > 0.0 ? length : T(1.0));
  const T scale = length > 0.0 ? quotient : T(0.0);  // N / |d|
  return {scale * d, r.energy, r.plastic_set, r.dissipated};
}

// The damper's force on n0: c ((v1 − v0)·n) n, pulling the ends' separation speed to zero.
inline Vec3 axial_damper(const Vec3& x0, const Vec3& x1, const Vec3& v0, const Vec3& v1,
                         double coefficient) {
  const Vec3 d = x1 - x0;
  const double length_squared = d.squaredNorm();
  if (length_squared <= 0.0) {
    return Vec3::Zero();
  }
  return (coefficient * (v1 - v0).dot(d) / length_squared) * d;
}

// Adds every bar's spring force; updates the plastic sets when the context allows.
void add_axial_spring_forces(ForceContext& context);
// Adds every bar's damper force, from the velocities v_{n−½}.
void add_axial_damper_forces(ForceContext& context);

// Σ ½ k (L − L0 − p)² over all bars, J.
double axial_spring_energy(const Model& model, const State& state, SpringEnergy which);
// Each bar's stiffness: k n nᵀ + (N / L)(I − n nᵀ) on its ends, as ±.
void add_axial_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink);

// The entry of spring_kinds.hpp.
extern const SpringKind kAxialSprings;

}  // namespace dinam
