#include "model/spring_colouring.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace dinam {

namespace {

// The colours taken at each node while one window is coloured, as bits: `words` 64-bit words a
// node (one is plenty for a mesh; a hub where hundreds of springs meet needs more).
struct TakenColours {
  int words = 1;
  std::vector<std::uint64_t> bits;  // (n_nodes × words)
  std::vector<Index> touched;       // nodes with some bit set, to clear them

  std::uint64_t* of(Index node) { return &bits[static_cast<std::size_t>(node) * words]; }
  void clear() {
    for (const Index n : touched) {
      std::fill_n(of(n), words, 0);
    }
    touched.clear();
  }
};

// Colours the blocks [window, window_end) greedily; false if some block found no free colour
// among 64 × taken.words (then nothing is kept).
bool colour_window(const std::vector<Index>& spring_nodes, std::size_t per_spring,
                   const SpringColouring& result, Index window, Index window_end,
                   TakenColours& taken, std::vector<int>& colour_of_block) {
  colour_of_block.clear();
  std::vector<std::uint64_t> used(static_cast<std::size_t>(taken.words));
  for (Index b = window; b < window_end; ++b) {
    const Index* first =
        &spring_nodes[static_cast<std::size_t>(SpringColouring::first_spring(b)) * per_spring];
    const Index* last = first + static_cast<std::size_t>(result.block_size(b)) * per_spring;
    std::fill(used.begin(), used.end(), 0);
    for (const Index* n = first; n != last; ++n) {
      const std::uint64_t* bits = taken.of(*n);
      for (int w = 0; w < taken.words; ++w) {
        used[w] |= bits[w];
      }
    }
    int colour = -1;
    for (int w = 0; w < taken.words && colour < 0; ++w) {
      if (used[w] != ~std::uint64_t{0}) {
        colour = 64 * w + std::countr_one(used[w]);
      }
    }
    if (colour < 0) {
      taken.clear();
      return false;
    }
    for (const Index* n = first; n != last; ++n) {
      std::uint64_t* bits = taken.of(*n);
      if (std::all_of(bits, bits + taken.words, [](std::uint64_t word) { return word == 0; })) {
        taken.touched.push_back(*n);
      }
      bits[colour / 64] |= std::uint64_t{1} << (colour % 64);
    }
    colour_of_block.push_back(colour);
  }
  taken.clear();
  return true;
}

}  // namespace

SpringColouring colour_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                               Index node_count) {
  SpringColouring result;
  result.spring_count = static_cast<Index>(spring_nodes.size()) / nodes_per_spring;
  const Index block_count = (result.spring_count + kSpringBlockSize - 1) / kSpringBlockSize;
  const auto per_spring = static_cast<std::size_t>(nodes_per_spring);
  TakenColours taken;
  taken.bits.assign(static_cast<std::size_t>(node_count), 0);
  std::vector<int> colour_of_block;  // in the current window
  result.offsets.push_back(0);
  for (Index window = 0; window < block_count; window += kColourWindowBlocks) {
    const Index window_end = std::min(block_count, window + kColourWindowBlocks);
    while (!colour_window(spring_nodes, per_spring, result, window, window_end, taken,
                          colour_of_block)) {
      taken.words *= 2;
      taken.bits.assign(static_cast<std::size_t>(node_count) * taken.words, 0);
    }
    // The window's blocks, colour by colour, ascending within one.
    const int colours = *std::max_element(colour_of_block.begin(), colour_of_block.end()) + 1;
    for (int c = 0; c < colours; ++c) {
      for (Index b = window; b < window_end; ++b) {
        if (colour_of_block[static_cast<std::size_t>(b - window)] == c) {
          result.blocks.push_back(b);
        }
      }
      result.offsets.push_back(static_cast<Index>(result.blocks.size()));
    }
  }
  return result;
}

}  // namespace dinam
