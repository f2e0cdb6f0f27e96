#pragma once
// Small models' stiffness and natural frequencies by dense linear algebra, for checks against
// closed-form mechanics: the stiffness matrix is taken by central differences of the real forces
// (every spring kind, as dynamics/ computes them), the masses are the model's lumped ones.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <vector>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"

namespace dinam::test {

// The free degrees of freedom of a model: 3 per free node, in node order.
struct FreeDofs {
  std::vector<int> dof_of_node;  // (n_nodes) first dof of each free node, −1 when pinned
  int count = 0;
};

inline FreeDofs free_dofs(const Model& model) {
  FreeDofs dofs;
  dofs.dof_of_node.assign(model.node_count(), -1);
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      dofs.dof_of_node[i] = dofs.count;
      dofs.count += 3;
    }
  }
  return dofs;
}

// M^{-½} K M^{-½} over the free dofs, symmetrised (a finite-difference K is symmetric only to
// rounding): its eigenvalues are ω².
inline Eigen::MatrixXd mass_normalised(const Model& model, const FreeDofs& dofs,
                                       const Eigen::MatrixXd& k) {
  Eigen::VectorXd inv_sqrt_mass(dofs.count);
  for (Index i = 0; i < model.node_count(); ++i) {
    if (dofs.dof_of_node[i] >= 0) {
      inv_sqrt_mass.segment<3>(dofs.dof_of_node[i])
          .setConstant(1.0 / std::sqrt(model.node_mass[i]));
    }
  }
  const Eigen::MatrixXd d = inv_sqrt_mass.asDiagonal() * k * inv_sqrt_mass.asDiagonal();
  return 0.5 * (d + d.transpose());
}

inline Eigen::VectorXd squared_frequencies(const Model& model, const FreeDofs& dofs,
                                           const Eigen::MatrixXd& k) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(mass_normalised(model, dofs, k),
                                                        Eigen::EigenvaluesOnly)
      .eigenvalues();
}

// λ_max of M^{-½} K M^{-½}: ω_max² of the stiffness matrix over the free dofs.
inline double max_frequency_squared(const Model& model, const FreeDofs& dofs,
                                    const Eigen::MatrixXd& k) {
  return squared_frequencies(model, dofs, k).maxCoeff();
}

// K over the free dofs at rest, −∂f/∂x by central differences of the elastic forces (no gravity,
// fields, wind, ground or dampers).
inline Eigen::MatrixXd finite_difference_stiffness(const Model& model, const FreeDofs& dofs) {
  ForceSwitches elastic;
  elastic.gravity = elastic.fields = elastic.wind = elastic.ground = false;
  elastic.axial_dampers = elastic.global_damping = false;
  State state = initial_state(model, 1e-6, elastic);
  Eigen::MatrixXd k_matrix = Eigen::MatrixXd::Zero(dofs.count, dofs.count);
  const double h = 1e-7;
  for (Index j = 0; j < model.node_count(); ++j) {
    for (int c = 0; c < 3 && dofs.dof_of_node[j] >= 0; ++c) {
      state.x = model.node_initial_x;
      state.x[j][c] += h;
      compute_forces(model, elastic, state);
      const std::vector<Vec3> plus = state.force;
      state.x[j][c] -= 2 * h;
      compute_forces(model, elastic, state);
      for (Index i = 0; i < model.node_count(); ++i) {
        if (dofs.dof_of_node[i] >= 0) {
          k_matrix.block<3, 1>(dofs.dof_of_node[i], dofs.dof_of_node[j] + c) =
              -(plus[i] - state.force[i]) / (2 * h);
        }
      }
    }
  }
  return k_matrix;
}

// The natural frequencies ω (rad/s) of the model at rest, ascending.
inline Eigen::VectorXd natural_frequencies(const Model& model) {
  const FreeDofs dofs = free_dofs(model);
  return squared_frequencies(model, dofs, finite_difference_stiffness(model, dofs))
      .cwiseMax(0.0)
      .cwiseSqrt();
}

}  // namespace dinam::test
