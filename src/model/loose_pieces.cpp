#include "model/loose_pieces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "model/disjoint_sets.hpp"
#include "model/model.hpp"
#include "model/tie_builder.hpp"

namespace dinam {

void note_loose_pieces(const SceneDescription& scene, Model& model) {
  const std::vector<std::uint8_t> tied = tied_nodes(model);
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ModelObject& object = model.objects[o];
    const Index first = object.first_node;
    const auto count = static_cast<std::size_t>(object.node_count);
    DisjointSets pieces_of(count);
    for (Index b = object.first_bar; b < object.first_bar + object.bar_count; ++b) {
      const Index a = pieces_of.find(model.bar_nodes[2 * b] - first);
      const Index c = pieces_of.find(model.bar_nodes[2 * b + 1] - first);
      if (a != c) {
        pieces_of.join(std::max(a, c), std::min(a, c));
      }
    }
    // Each piece's size and whether it holds a pinned or tied node, by root.
    std::vector<Index> size(count, 0);
    std::vector<char> held(count, 0);
    for (Index i = 0; i < object.node_count; ++i) {
      const Index root = pieces_of.find(i);
      size[root] += 1;
      held[root] = static_cast<char>(held[root] != 0 || model.pinned(first + i) ||
                                     tied[static_cast<std::size_t>(first + i)] != 0);
    }
    Index pieces = 0;
    Index free = 0;
    Index largest = 0;
    for (std::size_t r = 0; r < count; ++r) {
      if (size[r] > 0) {
        pieces += 1;
        free += held[r] == 0 ? 1 : 0;
        largest = std::max(largest, size[r]);
      }
    }
    if (pieces < 2 || free == 0) {
      continue;
    }
    const FileLoc& loc = scene.objects[o].mesh_loc;
    model.warnings.push_back(fmt::format(
        "{}: note: object '{}': its mesh is {} separate pieces that no bar joins (the largest has "
        "{} of its {} nodes), {} of them held by no pin: each moves on its own and falls away "
        "from the rest. If they belong together, join them in the mesh, pin them, or let them "
        "rest on each other with `contact: {{objects: true, self: true}}`",
        loc.known() ? loc.to_string() : "dinam", object.name, pieces, largest, object.node_count,
        free));
  }
}

}  // namespace dinam
