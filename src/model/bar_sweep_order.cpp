#include "model/bar_sweep_order.hpp"

#include <array>
#include <bit>
#include <cstdint>

#include "model/model.hpp"

namespace dinam {

std::vector<Index> bar_sweep_order(const Model& model) {
  constexpr int kColours = 64;
  std::vector<std::uint64_t> used(static_cast<std::size_t>(model.node_count()), 0);
  std::vector<int> colour(static_cast<std::size_t>(model.bar_count()), kColours);
  std::array<Index, kColours + 1> count{};
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index i = model.bar_nodes[2 * b];
    const Index j = model.bar_nodes[2 * b + 1];
    const std::uint64_t taken = used[i] | used[j];
    if (taken != ~std::uint64_t{0}) {
      colour[b] = std::countr_one(taken);
      used[i] |= std::uint64_t{1} << colour[b];
      used[j] |= std::uint64_t{1} << colour[b];
    }
    count[colour[b]] += 1;
  }
  std::array<Index, kColours + 1> next{};
  for (int c = 1; c <= kColours; ++c) {
    next[c] = next[c - 1] + count[c - 1];
  }
  std::vector<Index> order(static_cast<std::size_t>(model.bar_count()));
  for (Index b = 0; b < model.bar_count(); ++b) {
    order[next[colour[b]]++] = b;
  }
  return order;
}

}  // namespace dinam
