// The colouring of spring blocks (model/spring_colouring.hpp): what makes the force loops safe on
// any thread count and their order fixed.
#include "model/spring_colouring.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace dinam {
namespace {

// Checks what every colouring must be: each block once; no two blocks of one colour share a
// node; every colour's blocks within one window of kColourWindowBlocks, windows in order.
void expect_valid(const SpringColouring& colouring, const std::vector<Index>& spring_nodes,
                  int per_spring) {
  const Index blocks = (colouring.spring_count + kSpringBlockSize - 1) / kSpringBlockSize;
  std::vector<int> seen(static_cast<std::size_t>(blocks), 0);
  Index last_window = 0;
  for (Index c = 0; c < colouring.colour_count(); ++c) {
    std::set<Index> nodes;
    const Index window = colouring.blocks[colouring.offsets[c]] / kColourWindowBlocks;
    EXPECT_GE(window, last_window) << "colour " << c;
    last_window = window;
    for (Index k = colouring.offsets[c]; k < colouring.offsets[c + 1]; ++k) {
      const Index b = colouring.blocks[k];
      ++seen[static_cast<std::size_t>(b)];
      EXPECT_EQ(b / kColourWindowBlocks, window) << "colour " << c << " block " << b;
      const Index first = SpringColouring::first_spring(b);
      std::set<Index> block_nodes;
      for (Index s = first; s < first + colouring.block_size(b); ++s) {
        for (int j = 0; j < per_spring; ++j) {
          block_nodes.insert(
              spring_nodes[static_cast<std::size_t>(per_spring) * static_cast<std::size_t>(s) +
                           static_cast<std::size_t>(j)]);
        }
      }
      for (const Index n : block_nodes) {
        EXPECT_TRUE(nodes.insert(n).second) << "colour " << c << " shares node " << n;
      }
    }
  }
  for (Index b = 0; b < blocks; ++b) {
    EXPECT_EQ(seen[static_cast<std::size_t>(b)], 1) << "block " << b;
  }
}

// The bars of an n × n grid of nodes, row by row: consecutive bars are neighbours, as in a mesh.
std::vector<Index> grid_bars(Index n) {
  std::vector<Index> bars;
  for (Index row = 0; row < n; ++row) {
    for (Index col = 0; col < n; ++col) {
      const Index node = row * n + col;
      if (col + 1 < n) {
        bars.insert(bars.end(), {node, node + 1});
      }
      if (row + 1 < n) {
        bars.insert(bars.end(), {node, node + n});
      }
    }
  }
  return bars;
}

TEST(SpringColouring, ManyWindowsEachColouredApartWithDisjointNodesPerColour) {
  // 400 × 400 nodes: 319 200 bars in 4 988 blocks, three windows.
  const Index n = 400;
  const std::vector<Index> bars = grid_bars(n);
  const SpringColouring colouring = colour_springs(bars, 2, n * n);
  ASSERT_GT(colouring.spring_count / kSpringBlockSize, 2 * kColourWindowBlocks);
  expect_valid(colouring, bars, 2);
  // A mesh needs a few colours a window, not one a block.
  EXPECT_LT(colouring.colour_count(), 3 * 8);
}

TEST(SpringColouring, AModelWithinOneWindowIsColouredAsAWhole) {
  const Index n = 60;  // 7 080 bars, 111 blocks
  const std::vector<Index> bars = grid_bars(n);
  const SpringColouring colouring = colour_springs(bars, 2, n * n);
  expect_valid(colouring, bars, 2);
  // Greedy over one window: block 0 takes colour 0, and colour 0 comes first.
  EXPECT_EQ(colouring.blocks.front(), 0);
  EXPECT_LE(colouring.colour_count(), 8);
}

TEST(SpringColouring, AHubWhereMoreThanSixtyFourBlocksMeetTakesAColourEach) {
  // 100 blocks of springs that all end at node 0 (a hub of 6 400 spokes): no two may share a
  // colour, so the colouring needs 100 colours, past one 64-bit word of flags a node.
  std::vector<Index> spokes;
  for (Index s = 0; s < 100 * kSpringBlockSize; ++s) {
    spokes.insert(spokes.end(), {0, s + 1});
  }
  const SpringColouring colouring = colour_springs(spokes, 2, 100 * kSpringBlockSize + 1);
  expect_valid(colouring, spokes, 2);
  EXPECT_EQ(colouring.colour_count(), 100);
}

}  // namespace
}  // namespace dinam
