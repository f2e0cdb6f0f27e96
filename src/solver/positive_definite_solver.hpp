#pragma once
// Solves with a sparse symmetric positive-definite matrix (a stiffness, shifted): Eigen's
// simplicial Cholesky for small models, SuiteSparse's supernodal CHOLMOD from a number of
// unknowns on, where its dense blocks, through the single-threaded OpenBLAS, make it faster to
// factorise and to solve with. Both run on the calling thread alone (CHOLMOD's own OpenMP threads
// kept off), so both give the same bits for any thread count. They differ across machines:
// Eigen's simplicial factor gives the same bits on every machine built at the same vector width,
// CHOLMOD's depends on the OpenBLAS kernels chosen for the CPU.
#include <Eigen/Core>
#include <memory>

#include "solver/stiffness_matrix.hpp"

namespace dinam {

// Where the results start every render (the settled shape, Newton's equilibrium, and the natural
// modes), so that a scene's motion and its snapshots are the same on every machine: simplicial
// below 16 000 unknowns (every shipped scene), CHOLMOD above, several times faster at that size
// (a 100 000-bar cloth: 6.7 s a factorisation against 23 s with the reference BLAS;
// bench/notes/performance.md, "Settling and modes").
inline constexpr Eigen::Index kSupernodalFrom = 16000;
// Where speed is all that counts (the implicit integrator's steps): CHOLMOD through OpenBLAS
// factorises and solves faster from a couple of hundred unknowns on
// (bench/notes/implicit-integrator.md, "CHOLMOD through OpenBLAS").
inline constexpr Eigen::Index kFastestSupernodalFrom = 100;

class PositiveDefiniteSolver {
 public:
  // Factorises with CHOLMOD from `supernodal_from` unknowns on.
  explicit PositiveDefiniteSolver(Eigen::Index supernodal_from = kSupernodalFrom);
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
  // The same into `x`, reusing its storage.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

 private:
  struct Backend;
  Eigen::Index supernodal_from_;
  std::unique_ptr<Backend> backend_;
};

}  // namespace dinam
