#pragma once
// The pieces of a model's mesh: the sets of nodes its bars join, across objects. A piece that no
// pin holds moves as a body of its own; what it does where it lands sets how hard its steps are
// for the implicit integrator (estimate/implicit_cost.hpp, solver/landing_balance.hpp).
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

struct MeshPieces {
  std::vector<Index> piece;        // (n_nodes) the piece of each node, named by one of its nodes
  std::vector<int> size;           // (n_nodes) by piece: its nodes; 0 for a node that names none
  std::vector<std::uint8_t> held;  // (n_nodes) by piece: 1 where a pin or a tie holds it
};

MeshPieces mesh_pieces(const Model& model);

// Every node, piece by piece (the pieces in the order of their names, each piece's nodes in
// theirs): piece p's nodes are a run of pieces.size[p] from the first of them.
std::vector<Index> nodes_by_piece(const MeshPieces& pieces);

}  // namespace dinam
