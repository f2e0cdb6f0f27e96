#include "solver/constant_system.hpp"

#include "dynamics/force_kinds.hpp"
#include "model/model.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {

void ConstantSystem::set_springs(const Model& model, const State& state, const FreeDofs& dofs) {
  ForceSwitches springs = ForceSwitches::none();
  for (const ForceKind* kind : kForceKinds) {
    springs.*kind->switched = kind->spring != nullptr;
  }
  std::vector<Eigen::Triplet<double>> traces;
  add_block_traces(model, state, springs, dofs, traces);
  const Index nodes = dofs.count / 3;
  for (Index i = 0; i < nodes; ++i) {
    traces.emplace_back(i, i, 0.0);  // every free node's diagonal, for the inertia
  }
  springs_.resize(nodes, nodes);
  springs_.setFromTriplets(traces.begin(), traces.end());
}

bool ConstantSystem::factor(const Eigen::VectorXd& inertia,
                            const Eigen::SparseMatrix<double>& damping) {
  system_ = springs_;
  // The dampers' blocks reduced to their traces, as the springs' are.
  std::vector<Eigen::Triplet<double>> traces;
  for (int column = 0; column < damping.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator entry(damping, column); entry; ++entry) {
      if (entry.row() % 3 == entry.col() % 3) {
        traces.emplace_back(static_cast<int>(entry.row() / 3), static_cast<int>(entry.col() / 3),
                            entry.value());
      }
    }
  }
  if (!traces.empty()) {
    Eigen::SparseMatrix<double> dampers(system_.rows(), system_.cols());
    dampers.setFromTriplets(traces.begin(), traces.end());
    system_ += dampers;
  }
  for (Index i = 0; i < system_.rows(); ++i) {
    system_.coeffRef(i, i) += inertia[3 * i];
  }
  return solver_.factorize(system_);
}

void ConstantSystem::solve(const Eigen::VectorXd& r, Eigen::VectorXd& solved) const {
  const Index nodes = static_cast<Index>(system_.rows());
  solved.resize(r.size());
  column_.resize(nodes);
  for (int axis = 0; axis < 3; ++axis) {
    for (Index i = 0; i < nodes; ++i) {
      column_[i] = r[3 * i + axis];
    }
    solver_.solve(column_, solved_column_);
    for (Index i = 0; i < nodes; ++i) {
      solved[3 * i + axis] = solved_column_[i];
    }
  }
}

}  // namespace dinam
