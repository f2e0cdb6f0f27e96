#pragma once
// Springs in blocks of kSpringBlockSize consecutive ids, and the blocks grouped into colours so
// that no two blocks of one colour share a node. The force loops take the colours one after
// another and the blocks of a colour in parallel, each block on one thread in spring-id order:
// every node then receives its spring forces in one fixed order (colour, block, spring id),
// whatever the number of threads, so the motion is the same bit for bit on 1 thread or 16.
// Consecutive ids are neighbours in the mesh, so a block touches a compact patch of nodes (kind
// to the caches) and a few colours suffice (each costs the threads a barrier).
#include <algorithm>
#include <vector>

#include "core/types.hpp"

namespace dinam {

// Springs per block. A block's gathered inputs and its results (dynamics/spring_block.hpp) stay
// in the first-level cache between the passes over it.
inline constexpr Index kSpringBlockSize = 64;

struct SpringColouring {
  Index spring_count = 0;
  std::vector<Index> blocks;   // (n_blocks) block ids, colour by colour, ascending within one
  std::vector<Index> offsets;  // (n_colours + 1) colour c is blocks[offsets[c] .. offsets[c + 1])
  bool any_yield = false;      // some spring of this kind can flow plastically

  Index colour_count() const { return static_cast<Index>(offsets.size()) - 1; }
  // Block b holds the springs [first_spring(b), first_spring(b) + block_size(b)).
  static Index first_spring(Index block) { return block * kSpringBlockSize; }
  Index block_size(Index block) const {
    return std::min(kSpringBlockSize, spring_count - first_spring(block));
  }
};

// Greedy colouring of the blocks of springs given as `nodes_per_spring` node ids each (flat,
// spring by spring): each block takes the lowest colour that none of its nodes has yet.
SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count);

}  // namespace dinam
