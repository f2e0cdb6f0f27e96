// The sparse Cholesky solver (solver/positive_definite_solver.hpp): both of its factorisations
// solve, and CHOLMOD's runs on the calling thread alone, starting no threads of its own (Debian's
// CHOLMOD opens OpenMP regions of four threads in a large supernodal factorisation, which would
// spin against the thread team on a shared machine: bench/notes/threads.md).
#include "solver/positive_definite_solver.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace dinam {
namespace {

// The 7-point Laplacian of an n × n × n grid plus the identity: positive definite, and its
// factor has dense fronts of hundreds of rows (the grid's cross-sections), which is where
// CHOLMOD's supernodal factorisation opens its parallel regions.
SparseMatrix grid_laplacian(int n) {
  const int count = n * n * n;
  auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int at = id(i, j, k);
        triplets.emplace_back(at, at, 7.0);
        const int neighbours[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& b : neighbours) {
          if (b[0] < n && b[1] < n && b[2] < n) {
            const int other = id(b[0], b[1], b[2]);
            triplets.emplace_back(at, other, -1.0);
            triplets.emplace_back(other, at, -1.0);
          }
        }
      }
    }
  }
  SparseMatrix matrix(count, count);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

// The threads of this process, as Linux lists them.
long threads_of_this_process() {
  long count = 0;
  for ([[maybe_unused]] const auto& entry :
       std::filesystem::directory_iterator("/proc/self/task")) {
    ++count;
  }
  return count;
}

// x = A⁻¹ b solves A x = b to rounding, for each factorisation; the supernodal one leaves the
// process with the threads it had.
TEST(PositiveDefiniteSolver, BothFactorisationsSolveAndCholmodStartsNoThreads) {
  const SparseMatrix a = grid_laplacian(24);  // 13 824 unknowns
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  for (const Eigen::Index supernodal_from : {a.rows() + 1, Eigen::Index{1}}) {
    const long threads_before = threads_of_this_process();
    PositiveDefiniteSolver solver(supernodal_from);
    ASSERT_TRUE(solver.factorize(a));
    const Eigen::VectorXd x = solver.solve(b);
    // The Laplacian's condition number here is below 7 / 1: rounding leaves 1e-15 of |b|.
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << supernodal_from;
    EXPECT_EQ(threads_of_this_process(), threads_before) << supernodal_from;
  }
}

// A matrix that is not positive definite is an answer (false), not an error, for both.
TEST(PositiveDefiniteSolver, SaysWhereAMatrixIsNotPositiveDefinite) {
  SparseMatrix a = grid_laplacian(6);
  a.coeffRef(100, 100) = -1.0;
  for (const Eigen::Index supernodal_from : {a.rows() + 1, Eigen::Index{1}}) {
    PositiveDefiniteSolver solver(supernodal_from);
    EXPECT_FALSE(solver.factorize(a)) << supernodal_from;
  }
}

}  // namespace
}  // namespace dinam
