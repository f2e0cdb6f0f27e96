#pragma once
// Which pairs touch, for contact between objects and within one (object_contact.hpp).
//
// Candidates: every pair that could touch is found with a hash grid (contact_grid.hpp) of boxes
// grown by a skin s, and kept while no node of the scene's contact has moved by more than s since:
// the closest points of a pair are weighted means of its nodes, so a pair farther apart than
// reach + 2s when the candidates were found cannot have come within reach before then. Most steps
// check only the candidates; the search runs again once some node has moved by s. The pairs that
// touch are the same whenever the search ran and whatever the skin, so the motion depends on
// neither.
//
// The skin trades the two costs: a wider one finds more candidates to check every step, a
// narrower one searches more often. Each search sets it from the last interval, by counts alone
// (so that it is the same for any thread count and machine): a search costs about as much as
// checking kSearchCostInChecks candidates per primitive, and while the candidates checked since
// the last search cost more than the search, the skin narrows (to 1/20 of the largest radius at
// least); while they cost under a quarter of it, it widens again (to the largest radius at most).
// Falling cloth with little touching keeps the widest skin; cloth lying on itself, where every
// node has dozens of pairs within a radius, narrows it.
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

// Checking a candidate against searching again, per primitive (bar or node) of the contact;
// measured with bench_contact (docs/performance.md).
inline constexpr double kSearchCostInChecks = 80.0;

// Fills state.object_contact.touching, by features, with every pair nearer than the sum of its
// radii at state.x: its nodes, the closest points' weights and their separation.
void find_touching_pairs(const Model& model, State& state);

// Sizes the search's arrays of one entry per bar, triangle or node (state.object_contact), so that
// a step allocates only as the pairs grow; nothing without contact between objects.
void prepare_object_contact(const Model& model, State& state);

}  // namespace dinam
