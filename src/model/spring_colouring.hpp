#pragma once
// Springs in blocks of kSpringBlockSize consecutive ids, and the blocks grouped into colours so
// that no two blocks of one colour share a node. The force loops take the colours one after
// another and the blocks of a colour in parallel, each block on one thread in spring-id order:
// every node then receives its spring forces in one fixed order (colour, block, spring id),
// whatever the number of threads, so the motion is the same bit for bit on 1 thread or 16.
// Consecutive ids are neighbours in the mesh, so a block touches a compact patch of nodes (kind
// to the caches) and a few colours suffice (each costs the threads a barrier).
//
// The blocks are coloured window by window, kColourWindowBlocks consecutive blocks at a time, and
// a window's colours run before the next window's: the nodes a window touches stay in the cache
// while its colours pass over them. (Colouring all blocks at once made every colour sweep all the
// nodes; past a few hundred thousand springs the nodes no longer fit in the cache between the
// sweeps, and a step cost half as much again per spring.)
#include <algorithm>
#include <vector>

#include "core/types.hpp"

namespace dinam {

// Springs per block. A block's gathered inputs and its results (dynamics/spring_block.hpp) stay
// in the first-level cache between the passes over it.
inline constexpr Index kSpringBlockSize = 64;

// Blocks coloured together: 131 072 springs, whose nodes (a position and a force each) take 2 to
// 6 MB, well within the last-level cache. (512 blocks measured the same at a million springs and
// cost a model of 10⁵ springs its barriers three times over.)
inline constexpr Index kColourWindowBlocks = 2048;

struct SpringColouring {
  Index spring_count = 0;
  std::vector<Index> blocks;  // (n_blocks) block ids, colour by colour, ascending within one
  // (n_colours + 1) colour c is blocks[offsets[c] .. offsets[c + 1]); a window's colours are
  // numbered after the previous window's.
  std::vector<Index> offsets;
  bool any_yield = false;  // some spring of this kind can flow plastically

  Index colour_count() const { return static_cast<Index>(offsets.size()) - 1; }
  // Block b holds the springs [first_spring(b), first_spring(b) + block_size(b)).
  static Index first_spring(Index block) { return block * kSpringBlockSize; }
  Index block_size(Index block) const {
    return std::min(kSpringBlockSize, spring_count - first_spring(block));
  }
};

// Greedy colouring of the blocks of springs given as `nodes_per_spring` node ids each (flat,
// spring by spring), window by window: each block takes the lowest colour that none of its nodes
// has yet in its window.
SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count);

}  // namespace dinam
