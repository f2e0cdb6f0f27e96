#pragma once
// Which pairs touch, for contact between objects and within one (object_contact.hpp).
//
// Candidates and their skin are contact_candidates.hpp's; this is the narrow phase: which
// candidates touch now, by their closest points.
#include <cstdint>

#include "dynamics/state.hpp"

namespace dinam {

struct Model;
struct ObjectContact;

inline constexpr std::uint64_t kBarBarContact = 0;         // key >> 63 of a bar–bar pair
inline constexpr std::uint64_t kPointTriangleContact = 1;  // and of a node–triangle pair

// Side A's and side B's ids in a pair's key: bars, or a node and a triangle.
inline Index contact_side_a(std::uint64_t key) {
  return static_cast<Index>((key >> 32) & 0x7FFFFFFF);
}
inline Index contact_side_b(std::uint64_t key) {
  return static_cast<Index>(key & 0xFFFFFFFF);
}

// The sum of the pair's radii: it touches when its closest points are nearer.
double contact_reach(const ObjectContact& contact, std::uint64_t key);

// Whether pairs of primitives that name the same features are one contact (central differences:
// a node over a vertex where six triangles meet is pushed once), or each its own (the implicit
// integrator: every pair's penalty a continuous function of the positions, so that their sum is
// a potential Newton's line search can follow; merged, a node that moves off a vertex by a
// rounding error goes from one contact to two).
enum class PairMerging { kOnePerFeatures, kEveryPair };

// Fills state.object_contact.touching, by features (then by key), with every pair nearer than the
// sum of its radii at state.x: its nodes, the closest points' weights and their separation.
// Searches for candidates again first where they have gone stale (contact_candidates.hpp).
void find_touching_pairs(const Model& model, State& state,
                         PairMerging merging = PairMerging::kOnePerFeatures);

}  // namespace dinam
