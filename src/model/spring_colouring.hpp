#pragma once
// Springs grouped into colours so that no two springs of one colour share a node. The force loops
// run one colour after another, and within a colour in parallel: each node then receives its
// spring forces in one fixed order (colour by colour, by spring id within a colour), whatever the
// number of threads, so the motion is the same bit for bit on 1 thread or 16.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct SpringColouring {
  std::vector<Index> order;    // (n_springs) spring ids, colour by colour, ascending within one
  std::vector<Index> offsets;  // (n_colours + 1) colour c is order[offsets[c] .. offsets[c + 1])
  bool any_yield = false;      // some spring of this kind can flow plastically

  Index colour_count() const { return static_cast<Index>(offsets.size()) - 1; }
};

// Greedy colouring of springs given as `nodes_per_spring` node ids each (flat, spring by spring):
// each spring takes the lowest colour none of its nodes has yet.
SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count);

}  // namespace dinam
