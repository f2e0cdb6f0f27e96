#pragma once
// A sparse matrix set from triplets step after step, as the implicit step's dampers are: where
// the triplets fall on the same entries in the same order as the last time (no bar has broken),
// their values are summed into the kept matrix in place, in the triplets' order as Eigen's
// setFromTriplets sums duplicates, so the matrix is the same to the bit and nothing is allocated;
// else it is built afresh.
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace dinam {

class TripletMatrix {
 public:
  using Triplets = std::vector<Eigen::Triplet<double>>;

  const Eigen::SparseMatrix<double>& set(Index size, const Triplets& triplets);
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

 private:
  bool same_entries(Index size, const Triplets& triplets) const;

  Eigen::SparseMatrix<double> matrix_;
  std::vector<Index> rows_, cols_;  // the entries of the triplets the matrix was built from
  std::vector<Index> slots_;        // each triplet's place among the matrix's values
};

// into += add, in place where every entry of `add` is one of `into`'s (as Eigen's sum gives it,
// to the bit, without allocating); else by Eigen's sum, which widens `into`'s pattern.
void add_sparse(Eigen::SparseMatrix<double>& into, const Eigen::SparseMatrix<double>& add);

}  // namespace dinam
