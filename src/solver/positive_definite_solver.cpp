#include "solver/positive_definite_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

namespace dinam {

struct PositiveDefiniteSolver::Backend {
  bool analysed = false;
  bool supernodal = false;
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> simplicial;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholmod;
};

PositiveDefiniteSolver::PositiveDefiniteSolver() : backend_(std::make_unique<Backend>()) {
  // A matrix that is not positive definite is an answer here, not an error to print.
  backend_->cholmod.cholmod().print = 0;
}

PositiveDefiniteSolver::~PositiveDefiniteSolver() = default;

bool PositiveDefiniteSolver::factorize(const SparseMatrix& matrix) {
  Backend& b = *backend_;
  if (!b.analysed) {
    b.supernodal = matrix.rows() >= kSupernodalFrom;
    if (b.supernodal) {
      b.cholmod.analyzePattern(matrix);
    } else {
      b.simplicial.analyzePattern(matrix);
    }
    b.analysed = true;
  }
  if (b.supernodal) {
    b.cholmod.factorize(matrix);
    return b.cholmod.info() == Eigen::Success;
  }
  b.simplicial.factorize(matrix);
  return b.simplicial.info() == Eigen::Success;
}

Eigen::VectorXd PositiveDefiniteSolver::solve(const Eigen::VectorXd& rhs) const {
  const Backend& b = *backend_;
  return b.supernodal ? Eigen::VectorXd(b.cholmod.solve(rhs))
                      : Eigen::VectorXd(b.simplicial.solve(rhs));
}

}  // namespace dinam
