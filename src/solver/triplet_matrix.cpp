#include "solver/triplet_matrix.hpp"

#include <algorithm>

namespace dinam {

bool TripletMatrix::same_entries(Index size, const Triplets& triplets) const {
  if (matrix_.rows() != size || triplets.size() != rows_.size()) {
    return false;
  }
  for (std::size_t k = 0; k < triplets.size(); ++k) {
    if (triplets[k].row() != rows_[k] || triplets[k].col() != cols_[k]) {
      return false;
    }
  }
  return true;
}

const Eigen::SparseMatrix<double>& TripletMatrix::set(Index size, const Triplets& triplets) {
  if (same_entries(size, triplets)) {
    double* values = matrix_.valuePtr();
    std::fill(values, values + matrix_.nonZeros(), 0.0);
    for (std::size_t k = 0; k < triplets.size(); ++k) {
      values[slots_[k]] += triplets[k].value();
    }
    return matrix_;
  }
  matrix_.resize(size, size);
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();
  rows_.resize(triplets.size());
  cols_.resize(triplets.size());
  slots_.resize(triplets.size());
  const double* values = matrix_.valuePtr();
  for (std::size_t k = 0; k < triplets.size(); ++k) {
    rows_[k] = triplets[k].row();
    cols_[k] = triplets[k].col();
    slots_[k] = static_cast<Index>(&matrix_.coeffRef(rows_[k], cols_[k]) - values);
  }
  return matrix_;
}

namespace {

// Calls body(into's value, add's value) for each entry of `add`, found among `into`'s in its
// column (both sorted by row); false, before any call, where one is missing.
template <class Body>
bool for_each_shared_entry(Eigen::SparseMatrix<double>& into,
                           const Eigen::SparseMatrix<double>& add, const Body& body) {
  for (int pass = 0; pass < 2; ++pass) {
    for (Index column = 0; column < add.outerSize(); ++column) {
      Eigen::SparseMatrix<double>::InnerIterator at(into, column);
      for (Eigen::SparseMatrix<double>::InnerIterator entry(add, column); entry; ++entry) {
        while (at && at.row() < entry.row()) {
          ++at;
        }
        if (!at || at.row() != entry.row()) {
          return false;  // only on the first pass, which changes nothing
        }
        if (pass == 1) {
          body(at.valueRef(), entry.value());
        }
      }
    }
  }
  return true;
}

}  // namespace

void add_sparse(Eigen::SparseMatrix<double>& into, const Eigen::SparseMatrix<double>& add) {
  if (!into.isCompressed() || !add.isCompressed() ||
      !for_each_shared_entry(into, add, [](double& sum, double value) { sum += value; })) {
    into += add;
  }
}

}  // namespace dinam
