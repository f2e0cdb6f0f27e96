#pragma once
// The free degrees of freedom of a model, over which Newton's method and the implicit step work:
// x, y and z of each free node, in node order. Pinned nodes (driven or not) have none: their
// positions are given.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

// Entries of a sparse matrix over the free dofs, summed where they repeat (Eigen's
// setFromTriplets).
using DofTriplets = std::vector<Eigen::Triplet<double>>;

struct FreeDofs {
  std::vector<Index> first_dof;  // (n_nodes) the node's x dof (y, z follow), −1 when pinned
  Index count = 0;
};
FreeDofs free_dofs(const Model& model);

// A per-node array (forces, positions) as a vector over the free dofs.
Eigen::VectorXd free_part(const FreeDofs& dofs, const std::vector<Vec3>& per_node);
// The same into `free`, its storage reused.
void free_part(const FreeDofs& dofs, const std::vector<Vec3>& per_node, Eigen::VectorXd& free);

// The lumped mass of each free degree of freedom, kg: each free node's mass three times, in the
// order of `dofs`. M of Newton's shift μM and of the modes' K φ = ω² M φ.
Eigen::VectorXd free_masses(const Model& model, const FreeDofs& dofs);

}  // namespace dinam
