#pragma once
// The constant matrix of the solver for stiff threads (quasi_newton.hpp): over the free nodes,
//   A = (1/h² + α/h) M + L + D̄,
// L the springs' stiffness reduced to what no rotation changes (add_block_traces: a bar's k in
// every direction, as projective dynamics' springs have it), taken once at the start of a run,
// and D̄ the dampers' alike. A ⊗ I₃ stands for the incremental potential's Hessian: exact for the
// inertia, a bar's stretch and a straight wire's bend, and near it while the cloth turns and
// folds, where the Hessian itself changes at every step. It is factorised once for a step's
// length (a scalar matrix a ninth the size of the Hessian's), and each solve is three
// back-substitutions, x, y and z, with the one factor.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "dynamics/free_dofs.hpp"
#include "solver/positive_definite_solver.hpp"

namespace dinam {

struct Model;
struct State;

class ConstantSystem {
 public:
  // L from the springs at `state` (their stiffness's rotation-invariant part: the start of the
  // run), over `dofs`' free nodes.
  void set_springs(const Model& model, const State& state, const FreeDofs& dofs);
  bool has_springs() const { return springs_.rows() > 0; }

  // Factorises A for this inertia (M/h² + α M/h, over the free dofs, three alike a node) and
  // dampers' Hessian `damping` (over the free dofs); false where A is not positive definite.
  bool factor(const Eigen::VectorXd& inertia, const Eigen::SparseMatrix<double>& damping);

  // (A ⊗ I₃)⁻¹ r, over the free dofs.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd& solved) const;

 private:
  Eigen::SparseMatrix<double> springs_;  // L, over the free nodes
  Eigen::SparseMatrix<double> system_;   // A, factorised last
  PositiveDefiniteSolver solver_{kFastestSupernodalFrom};
  // A solve's right-hand sides and solutions, x, y and z in turn, kept so that none allocates.
  mutable Eigen::VectorXd column_, solved_column_;
};

}  // namespace dinam
