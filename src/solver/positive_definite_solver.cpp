#include "solver/positive_definite_solver.hpp"

#include <omp.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <vector>

namespace dinam {

struct PositiveDefiniteSolver::Backend {
  bool analysed = false;
  bool supernodal = false;
  // The pattern analysed: the compressed matrix's column starts and row indices.
  std::vector<SparseMatrix::StorageIndex> outer, inner;
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> simplicial;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholmod;
};

PositiveDefiniteSolver::PositiveDefiniteSolver(Eigen::Index supernodal_from)
    : supernodal_from_(supernodal_from), backend_(std::make_unique<Backend>()) {
  // A matrix that is not positive definite is an answer here, not an error to print.
  backend_->cholmod.cholmod().print = 0;
}

PositiveDefiniteSolver::~PositiveDefiniteSolver() = default;

namespace {

// Debian's CHOLMOD opens OpenMP parallel regions of four threads in its supernodal factorisation,
// whatever share of the machine the process has, and libgomp's threads spin before they sleep:
// the collapse on a shared machine that the thread team replaced (bench/notes/threads.md). With no
// active level allowed, every region runs on the thread that opens it. The setting is the calling
// thread's (OpenMP's max-active-levels-var), so it is made before each call into CHOLMOD.
void keep_cholmod_on_this_thread() {
  omp_set_max_active_levels(0);
}

}  // namespace

bool PositiveDefiniteSolver::factorize(const SparseMatrix& matrix) {
  Backend& b = *backend_;
  const auto* outer = matrix.outerIndexPtr();
  const auto* inner = matrix.innerIndexPtr();
  const auto columns = static_cast<std::size_t>(matrix.cols()) + 1;
  const auto entries = static_cast<std::size_t>(matrix.nonZeros());
  const bool same_pattern = b.analysed && matrix.isCompressed() && b.outer.size() == columns &&
                            b.inner.size() == entries &&
                            std::equal(b.outer.begin(), b.outer.end(), outer) &&
                            std::equal(b.inner.begin(), b.inner.end(), inner);
  if (!same_pattern) {
    b.analysed = false;
  }
  if (!b.analysed) {
    if (matrix.isCompressed()) {
      b.outer.assign(outer, outer + columns);
      b.inner.assign(inner, inner + entries);
    }
    b.supernodal = matrix.rows() >= supernodal_from_;
    if (b.supernodal) {
      keep_cholmod_on_this_thread();
      b.cholmod.analyzePattern(matrix);
    } else {
      b.simplicial.analyzePattern(matrix);
    }
    b.analysed = true;
  }
  if (b.supernodal) {
    keep_cholmod_on_this_thread();
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

void PositiveDefiniteSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const {
  const Backend& b = *backend_;
  if (b.supernodal) {
    x = b.cholmod.solve(rhs);
  } else {
    x = b.simplicial.solve(rhs);
  }
}

}  // namespace dinam
