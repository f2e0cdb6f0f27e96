#pragma once
// Solves with a sparse symmetric positive-definite matrix (a stiffness, shifted): Eigen's
// simplicial Cholesky for small models, SuiteSparse's supernodal CHOLMOD from kSupernodalFrom
// unknowns on, where its dense blocks make it several times faster (a 100 000-bar cloth: 6.7 s a
// factorisation against 23 s; docs/performance.md, "Settling and modes"). Both give the same
// bits on any machine and thread count: CHOLMOD's blocks go through the BLAS, and Debian's
// reference BLAS is single-threaded and uses no fused multiply-add. (An optimised BLAS installed
// as the system's libblas would be faster and make the last bits depend on the machine.)
#include <Eigen/Core>
#include <memory>

#include "solver/stiffness_matrix.hpp"

namespace dinam {

inline constexpr Eigen::Index kSupernodalFrom = 16000;

class PositiveDefiniteSolver {
 public:
  PositiveDefiniteSolver();
  ~PositiveDefiniteSolver();
  PositiveDefiniteSolver(const PositiveDefiniteSolver&) = delete;
  PositiveDefiniteSolver& operator=(const PositiveDefiniteSolver&) = delete;

  // Factorises `matrix` (its lower triangle is read); false where it is not positive definite.
  // Its pattern is analysed at the first call and again wherever it differs from the last one
  // analysed (a pair of objects or a node on the ground that newly couples two unknowns): a
  // factorisation with another pattern's analysis would be wrong.
  bool factorize(const SparseMatrix& matrix);
  // x = matrix⁻¹ b, after a factorize that returned true.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Backend;
  std::unique_ptr<Backend> backend_;
};

}  // namespace dinam
