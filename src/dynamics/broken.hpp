#pragma once
// What tearing leaves of a kind of spring (or of the faces): a flag per item, 1 once it has
// broken, and no flags at all where the model cannot tear (State's *_broken arrays). Every loop
// over springs, faces or bars asks here, so that "broken" means one thing everywhere: a broken
// spring exerts no force, stores no energy, adds no stiffness, damps nothing, catches no wind and
// touches nothing.
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace dinam {

inline bool is_broken(const std::vector<std::uint8_t>& broken, Index item) {
  return !broken.empty() && broken[item] != 0;
}

// The flags as the vectorised spring blocks read them, or null where the model cannot tear.
inline const std::uint8_t* broken_flags(const std::vector<std::uint8_t>& broken) {
  return broken.empty() ? nullptr : broken.data();
}

// Σ value(s) over the `count` items not broken, in id order.
template <class Value>
double sum_over_intact(const std::vector<std::uint8_t>& broken, Index count, const Value& value) {
  double sum = 0.0;
  for (Index s = 0; s < count; ++s) {
    if (!is_broken(broken, s)) {
      sum += value(s);
    }
  }
  return sum;
}

}  // namespace dinam
