// The bending springs' stiffness matrices, for Newton's method (solver/), apart from their forces:
// bending_spring.cpp holds the step's loop, which is built for the widest vectors the machine has
// (src/dynamics/CMakeLists.txt), while this, whose small dense products Eigen vectorises with
// sums ordered by the vector width, is built with the rest of the program, so that a shape
// settled by Newton's method has the same bits whatever the width.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynamics/bending_spring.hpp"
#include "dynamics/stiffness.hpp"
#include "model/model.hpp"

namespace dinam {

LocalStiffness<3> bending_spring_stiffness(const std::array<Vec3, 3>& at, double rest_angle,
                                           double stiffness, double plastic_set, double yield) {
  const Vec3 e1 = at[0] - at[1];
  const Vec3 e2 = at[2] - at[1];
  const double l1_squared = e1.squaredNorm();
  const double l2_squared = e2.squaredNorm();
  const bool in_line =
      e1.cross(e2).squaredNorm() <= kBendingMinSine * kBendingMinSine * l1_squared * l2_squared &&
      e1.dot(e2) < 0.0 && l1_squared > 0.0 && l2_squared > 0.0;
  if (!in_line) {
    return local_stiffness<3>(at, [&](const auto& x) {
      const auto r = bending_spring(x[0], x[1], x[2], rest_angle, stiffness, plastic_set, yield);
      return std::array{r.force_a, r.force_c, r.force_b};
    });
  }
  // The curvature of E in ψ at ψ = 0 (bending_spring: ½ k ψ² for a straight rest; 2b of the
  // cap a + b ψ² + c ψ⁴ for a bent one).
  const double rest_deflection = std::numbers::pi - rest_angle - plastic_set;
  const double width = std::min(rest_deflection, kBendingStraightCap);
  const double curvature =
      rest_deflection > 0.0 ? stiffness * (1.0 - 1.5 * rest_deflection / width) : stiffness;
  const Vec3 along = e2 / std::sqrt(l2_squared);
  const Mat3 across = Mat3::Identity() - along * along.transpose();
  Eigen::Matrix<double, 3, 9> j;
  const double inverse_l1 = 1.0 / std::sqrt(l1_squared);
  const double inverse_l2 = 1.0 / std::sqrt(l2_squared);
  j << inverse_l1 * across, -(inverse_l1 + inverse_l2) * across, inverse_l2 * across;
  return curvature * j.transpose() * j;
}

void add_bending_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  add_spring_stiffness<3>(model.bend_count(), model.bend_nodes, state.bend_broken, state.x, sink,
                          [&](Index s, const std::array<Vec3, 3>& at) {
                            return bending_spring_stiffness(
                                at, model.bend_rest_angle[s], model.bend_stiffness[s],
                                plastic_set_of(state.bend_plastic_set, s),
                                yield_limit(model.bend_yield_moment, s));
                          });
}

}  // namespace dinam
