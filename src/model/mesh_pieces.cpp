#include "model/mesh_pieces.hpp"

#include <algorithm>
#include <numeric>

#include "model/disjoint_sets.hpp"
#include "model/model.hpp"
#include "model/tie_builder.hpp"

namespace dinam {

MeshPieces mesh_pieces(const Model& model) {
  const auto n = static_cast<std::size_t>(model.node_count());
  DisjointSets sets(n);
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index root_i = sets.find(model.bar_nodes[2 * b]);
    const Index root_j = sets.find(model.bar_nodes[2 * b + 1]);
    if (root_i != root_j) {
      sets.join(root_i, root_j);
    }
  }
  MeshPieces pieces{sets.roots(), std::vector<int>(n, 0), std::vector<std::uint8_t>(n, 0)};
  const std::vector<std::uint8_t> tied = tied_nodes(model);
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index piece = pieces.piece[i];
    pieces.size[piece] += 1;
    pieces.held[piece] = pieces.held[piece] != 0 || model.pinned(i) || tied[i] != 0 ? 1 : 0;
  }
  return pieces;
}

std::vector<Index> nodes_by_piece(const MeshPieces& pieces) {
  std::vector<Index> order(pieces.piece.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return pieces.piece[a] < pieces.piece[b]; });
  return order;
}

}  // namespace dinam
