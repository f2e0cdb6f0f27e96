#include "model/spring_colouring.hpp"

#include <algorithm>

namespace dinam {

SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count) {
  SpringColouring result;
  result.spring_count = static_cast<Index>(spring_nodes.size()) / nodes_per_spring;
  const Index block_count = (result.spring_count + kSpringBlockSize - 1) / kSpringBlockSize;
  // Colours taken at each node, as a growing list of flags per node (few colours meet at a node).
  std::vector<std::vector<bool>> taken(static_cast<std::size_t>(node_count));
  std::vector<Index> colour(static_cast<std::size_t>(block_count));
  Index colours = 0;
  for (Index b = 0; b < block_count; ++b) {
    const auto per_spring = static_cast<std::size_t>(nodes_per_spring);
    const auto* first =
        &spring_nodes[static_cast<std::size_t>(SpringColouring::first_spring(b)) * per_spring];
    const auto* last = first + static_cast<std::size_t>(result.block_size(b)) * per_spring;
    auto free = [&](Index candidate) {
      return std::none_of(first, last, [&](Index n) {
        const auto& flags = taken[static_cast<std::size_t>(n)];
        return static_cast<std::size_t>(candidate) < flags.size() &&
               flags[static_cast<std::size_t>(candidate)];
      });
    };
    Index c = 0;
    while (!free(c)) {
      ++c;
    }
    for (const auto* n = first; n != last; ++n) {
      auto& flags = taken[static_cast<std::size_t>(*n)];
      flags.resize(std::max(flags.size(), static_cast<std::size_t>(c) + 1), false);
      flags[static_cast<std::size_t>(c)] = true;
    }
    colour[static_cast<std::size_t>(b)] = c;
    colours = std::max(colours, c + 1);
  }
  result.offsets.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (const Index c : colour) {
    ++result.offsets[static_cast<std::size_t>(c) + 1];
  }
  for (Index c = 0; c < colours; ++c) {
    result.offsets[c + 1] += result.offsets[c];
  }
  result.blocks.resize(static_cast<std::size_t>(block_count));
  std::vector<Index> next(result.offsets.begin(), result.offsets.end() - 1);
  for (Index b = 0; b < block_count; ++b) {
    result.blocks[static_cast<std::size_t>(next[colour[b]]++)] = b;
  }
  return result;
}

}  // namespace dinam
