#include "model/edge_collapse.hpp"

#include <algorithm>

#include "model/disjoint_sets.hpp"

namespace dinam {

namespace {

// One pass: merges the ends of the bars shorter than `tolerance`, shortest first, into groups
// that reach at most `tolerance` from their first node. Returns the group of every node (its
// smallest id) and the number of merges.
std::pair<std::vector<Index>, Index> merge_pass(const std::vector<Vec3>& nodes,
                                                const std::vector<std::pair<Index, Index>>& edges,
                                                double tolerance) {
  std::vector<std::pair<double, std::size_t>> short_edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double length = (nodes[edges[e].second] - nodes[edges[e].first]).norm();
    if (length < tolerance) {
      short_edges.emplace_back(length, e);
    }
  }
  std::sort(short_edges.begin(), short_edges.end());
  DisjointSets groups(nodes.size());
  std::vector<double> reach(nodes.size(), 0.0);
  Index merges = 0;
  for (const auto& [length, e] : short_edges) {
    Index a = groups.find(edges[e].first);
    Index b = groups.find(edges[e].second);
    if (a == b) {
      continue;  // both ends already merged through other short bars
    }
    if (b < a) {
      std::swap(a, b);
    }
    const double joined = std::max(reach[a], (nodes[b] - nodes[a]).norm() + reach[b]);
    if (joined > tolerance) {
      continue;  // left for the next pass, where each group is one node
    }
    groups.join(b, a);
    reach[a] = joined;
    ++merges;
  }
  return {groups.roots(), merges};
}

}  // namespace

EdgeCollapse collapse_short_edges(const WeldResult& weld,
                                  const std::vector<std::pair<Index, Index>>& edges,
                                  double fraction) {
  EdgeCollapse result;
  result.weld = weld;
  if (edges.empty() || fraction <= 0.0) {
    return result;
  }
  std::vector<double> lengths(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    lengths[e] = (weld.nodes[edges[e].second] - weld.nodes[edges[e].first]).norm();
  }
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  result.median_length = *middle;
  result.tolerance = fraction * result.median_length;

  // Passes until no bar shorter than the tolerance is left (a group of the last pass is one node
  // in the next, so a bar between two groups that could not join yet can then).
  std::vector<std::pair<Index, Index>> current = edges;
  for (int pass = 0; pass < 16; ++pass) {
    const auto [group, merges] = merge_pass(result.weld.nodes, current, result.tolerance);
    if (merges == 0) {
      break;
    }
    result.merged_nodes += merges;
    // New ids in order of each group's first node, which keeps its place.
    std::vector<Index> new_id(group.size(), -1);
    std::vector<Vec3> nodes;
    for (std::size_t w = 0; w < group.size(); ++w) {
      const auto root = static_cast<std::size_t>(group[w]);
      if (new_id[root] < 0) {
        new_id[root] = static_cast<Index>(nodes.size());
        nodes.push_back(result.weld.nodes[root]);
      }
    }
    for (Index& id : result.weld.node_of_vertex) {
      id = new_id[static_cast<std::size_t>(group[static_cast<std::size_t>(id)])];
    }
    result.weld.nodes = std::move(nodes);
    std::vector<std::pair<Index, Index>> next;
    for (const auto& [a, b] : current) {
      const Index na = new_id[static_cast<std::size_t>(group[static_cast<std::size_t>(a)])];
      const Index nb = new_id[static_cast<std::size_t>(group[static_cast<std::size_t>(b)])];
      if (na != nb) {
        next.emplace_back(std::min(na, nb), std::max(na, nb));
      }
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    current = std::move(next);
  }
  return result;
}

}  // namespace dinam
