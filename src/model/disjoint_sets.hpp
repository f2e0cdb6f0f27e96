#pragma once
// Disjoint sets of the ids 0 … n − 1 (union–find with path halving), each set named by its root:
// the groups of short bars that collapse into one node (edge_collapse.cpp) and the pieces of a
// mesh that no bar joins (loose_pieces.cpp).
#include <cstddef>
#include <numeric>
#include <vector>

#include "core/types.hpp"

namespace dinam {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }

  // The root of `id`'s set, halving the path there on the way.
  Index find(Index id) {
    while (parent_[id] != id) {
      parent_[id] = parent_[parent_[id]];
      id = parent_[id];
    }
    return id;
  }

  // Joins the set rooted at `root` into the one rooted at `into` (both roots).
  void join(Index root, Index into) { parent_[root] = into; }

  // Each id's root.
  std::vector<Index> roots() {
    std::vector<Index> root(parent_.size());
    for (std::size_t id = 0; id < parent_.size(); ++id) {
      root[id] = find(static_cast<Index>(id));
    }
    return root;
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace dinam
