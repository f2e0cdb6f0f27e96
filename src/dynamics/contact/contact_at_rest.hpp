#pragma once
// Contact pairs that already overlap in the scene's starting positions. The penalty pushes such a
// pair apart from the first step with an energy that nothing in the scene supplied (a radius of a
// metre on a cloth of centimetre bars sets the whole cloth against itself), so a radius or a
// placement that makes them is the user's to fix before the run (app/ says so at the key).
#include <cstdint>
#include <optional>

#include "core/types.hpp"

namespace dinam {

struct Model;

struct RestOverlap {
  Index pairs = 0;        // pairs of features nearer than their reach at rest
  std::uint64_t key = 0;  // the deepest one's primitives (contact_pairs.hpp)
  Index object_a = 0;     // its sides' objects
  Index object_b = 0;
  double distance = 0.0;  // m, between its closest points
  double reach = 0.0;     // m, the sum of its radii
};

// The deepest of the pairs that overlap by more than `tolerance` × their reach at the model's
// initial positions, with their count; nothing when none does or contact between objects is off.
std::optional<RestOverlap> contact_overlap_at_rest(const Model& model, double tolerance);

}  // namespace dinam
