#include "model/spring_colouring.hpp"

#include <algorithm>

namespace dinam {

SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count) {
  const auto spring_count = static_cast<Index>(spring_nodes.size()) / nodes_per_spring;
  // Colours used at each node, as a growing list of flags per node (few colours meet at a node).
  std::vector<std::vector<bool>> used(static_cast<std::size_t>(node_count));
  std::vector<Index> colour(static_cast<std::size_t>(spring_count));
  Index colours = 0;
  for (Index s = 0; s < spring_count; ++s) {
    const Index* nodes = &spring_nodes[static_cast<std::size_t>(s) * nodes_per_spring];
    Index c = 0;
    auto taken = [&](Index candidate) {
      return std::any_of(nodes, nodes + nodes_per_spring, [&](Index n) {
        const auto& flags = used[static_cast<std::size_t>(n)];
        return static_cast<std::size_t>(candidate) < flags.size() &&
               flags[static_cast<std::size_t>(candidate)];
      });
    };
    while (taken(c)) {
      ++c;
    }
    for (int k = 0; k < nodes_per_spring; ++k) {
      auto& flags = used[static_cast<std::size_t>(nodes[k])];
      flags.resize(std::max(flags.size(), static_cast<std::size_t>(c) + 1), false);
      flags[static_cast<std::size_t>(c)] = true;
    }
    colour[static_cast<std::size_t>(s)] = c;
    colours = std::max(colours, c + 1);
  }
  SpringColouring result;
  result.offsets.assign(static_cast<std::size_t>(colours) + 1, 0);
  for (const Index c : colour) {
    ++result.offsets[static_cast<std::size_t>(c) + 1];
  }
  for (Index c = 0; c < colours; ++c) {
    result.offsets[c + 1] += result.offsets[c];
  }
  result.order.resize(static_cast<std::size_t>(spring_count));
  std::vector<Index> next(result.offsets.begin(), result.offsets.end() - 1);
  for (Index s = 0; s < spring_count; ++s) {
    result.order[static_cast<std::size_t>(next[colour[s]]++)] = s;
  }
  return result;
}

}  // namespace dinam
