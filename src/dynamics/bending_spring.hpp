#pragma once
// Bending springs: a rotational spring at node c between the bars c–a and c–b, on the angle θ
// between them, elastoplastic in θ − θ0.
#include <limits>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

struct BendingSpringResult {
  Vec3 force_a, force_c, force_b;  // N
  double energy;                   // J, ½ k (θ − θ0 − p)²
  double plastic_set = 0.0;        // rad
  double dissipated = 0.0;         // J
};

// With u = (xa − xc)/|xa − xc|, w = (xb − xc)/|xb − xc|, c = u·w, s = |u × w|, θ = atan2(s, c):
//   ∂θ/∂xa = −(w − c u) / (|xa − xc| s),  ∂θ/∂xb = −(u − c w) / (|xb − xc| s),
//   ∂θ/∂xc = −(∂θ/∂xa + ∂θ/∂xb),
// each a unit direction in the plane of the bars over a length, and the force is −M ∇θ with
// M = k (θ − θ0 − p) flattened at ±My. When the bars are (nearly) straight the plane is
// undefined; then M → 0 for a straight rest angle (the force fades smoothly), and otherwise the
// force is left out for that one configuration (bounded, no NaN) rather than given a random
// direction.
BendingSpringResult bending_spring(const Vec3& xa, const Vec3& xc, const Vec3& xb,
                                   double rest_angle, double stiffness, double plastic_set = 0.0,
                                   double yield = std::numeric_limits<double>::infinity());

void add_bending_spring_forces(ForceContext& context);
double bending_spring_energy(const Model& model, const State& state);

}  // namespace dinam
