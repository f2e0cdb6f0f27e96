#pragma once
// Axial springs: one per bar, k = EA / L0, linear in the change of length.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

struct AxialSpringResult {
  Vec3 force_on_n0;  // N; the force on n1 is its negative
  double energy;     // J, ½ k (L − L0)²
};

// The kernel over one bar's two nodes. With d = x1 − x0, L = |d|, n = d / L:
// f0 = k (L − L0) n (a stretched bar pulls n0 towards n1), f1 = −f0.
// A bar of zero current length has no direction and gives no force.
inline AxialSpringResult axial_spring(const Vec3& x0, const Vec3& x1, double rest_length,
                                      double stiffness) {
  const Vec3 d = x1 - x0;
  const double length = d.norm();
  const double extension = length - rest_length;
  if (length <= 0.0) {
    return {Vec3::Zero(), 0.5 * stiffness * extension * extension};
  }
  return {(stiffness * extension / length) * d, 0.5 * stiffness * extension * extension};
}

// Adds every bar's axial force to `force` (n_nodes).
void add_axial_spring_forces(const Model& model, const std::vector<Vec3>& x,
                             std::vector<Vec3>& force);

// Σ ½ k (L − L0)² over all bars, J.
double axial_spring_energy(const Model& model, const std::vector<Vec3>& x);

}  // namespace dinam
