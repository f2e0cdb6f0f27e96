#pragma once
// What both phases of the pair search (contact_candidates.hpp, contact_pairs.hpp) ask of a pair
// of primitives: its key, whether its sides are broken or may touch at all, and its closest points
// when they are within a distance.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/types.hpp"
#include "dynamics/broken.hpp"
#include "dynamics/contact/contact_grid.hpp"
#include "dynamics/contact/contact_pairs.hpp"
#include "dynamics/state.hpp"
#include "model/model.hpp"

namespace dinam {

inline std::uint64_t pair_key(std::uint64_t kind, Index a, Index b) {
  return kind << 63 | static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint64_t>(b);
}

inline Box box_of(const Vec3& a, const Vec3& b, double grow) {
  return {a.cwiseMin(b).array() - grow, a.cwiseMax(b).array() + grow};
}

inline bool objects_may_touch(const ObjectContact& contact, Index object_a, Index object_b) {
  return object_a == object_b
             ? contact.object_self[object_a] != 0
             : contact.object_between[object_a] != 0 && contact.object_between[object_b] != 0;
}

inline bool bar_broken(const State& state, Index bar) {
  return is_broken(state.bar_broken, bar);
}

inline bool triangle_broken(const ObjectContact& contact, const State& state, Index triangle) {
  return is_broken(state.face_broken, contact.triangle_face[triangle]);
}

// The pair's closest points' weights (A's positive, B's negative) and separation p_A − p_B.
struct Closest {
  std::array<double, 4> weights;
  Vec3 separation;
};

// The pair's closest points when they are nearer than `distance` at positions x; nothing
// otherwise (found cheaply, by the sides' boxes, for most pairs that are not).
std::optional<Closest> closest_within(const ContactCandidate& pair, const std::vector<Vec3>& x,
                                      double distance);

}  // namespace dinam
