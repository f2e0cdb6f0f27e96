#pragma once
// The bar between two nodes, by a hash of the ordered pair (tearing finds the bars each spring and
// face stands on through it).
#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "model/model.hpp"

namespace dinam {

class BarLookup {
 public:
  explicit BarLookup(const Model& model) {
    bars_.reserve(static_cast<std::size_t>(model.bar_count()));
    for (Index b = 0; b < model.bar_count(); ++b) {
      bars_.emplace(key(model.bar_nodes[2 * b], model.bar_nodes[2 * b + 1]), b);
    }
  }
  // The bar from n0 to n1 (either way round), or −1.
  Index find(Index n0, Index n1) const {
    const auto found = bars_.find(key(n0, n1));
    return found == bars_.end() ? -1 : found->second;
  }

 private:
  static std::uint64_t key(Index a, Index b) {
    const auto low = static_cast<std::uint64_t>(std::min(a, b));
    const auto high = static_cast<std::uint64_t>(std::max(a, b));
    return (high << 32) | low;
  }
  std::unordered_map<std::uint64_t, Index> bars_;
};

}  // namespace dinam
