#pragma once
// What contact between objects keeps from step to step (the friction's stick springs) and the
// broad phase's arrays, reused so that a step allocates nothing once they have grown.
#include <array>
#include <compare>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/contact/contact_grid.hpp"

namespace dinam {

// What a contact is between, whichever pair of primitives found it (contact_pairs.cpp): a node
// and a node (a, b), a node and a bar's inside (node a, bar b–c), a node and a triangle's inside
// (node a, triangle b), or the insides of two bars (a, b). Contacts are summed, and matched with
// the step before, in this order.
struct ContactFeatures {
  enum Kind : std::int32_t { kNodeNode, kNodeEdge, kNodeTriangle, kEdgeEdge };
  std::int32_t kind = kNodeNode;
  Index a = 0, b = 0, c = 0;

  // NOLINTNEXTLINE(modernize-use-nullptr): a false alarm on the defaulted comparison
  auto operator<=>(const ContactFeatures&) const = default;
};

// One touching pair: side A (a bar, or a node) against side B (a bar, or a triangle).
struct ContactPoint {
  ContactFeatures features;
  std::uint64_t key = 0;            // kind, A's id, B's id of the pair of primitives that found it
  std::array<Index, 4> nodes{};     // A's nodes, then B's (a node–triangle pair: 1 + 3)
  std::array<double, 4> weights{};  // the closest points' weights, A's ≥ 0, B's ≤ 0 (negated)
  Vec3 separation = Vec3::Zero();   // m, p_A − p_B between the closest points
  Vec3 slip = Vec3::Zero();         // m, the stick spring's tangential stretch
  double energy = 0.0;              // J, ½ k δ² of the normal penalty
  bool sliding = false;
  // The implicit integrator's: the speed the pair struck at (m/s; 0 where there is none to give
  // back), its penalty's ω (rad/s) and the phase backward Euler has turned the impact through
  // since (rad, atan(ω h) a step): the speed times the restitution is given back if the pair
  // parts before that reaches 2π, two of the scheme's half periods.
  double struck = 0.0;
  double impact_omega = 0.0;
  double impact_phase = 0.0;
  // A node–triangle pair: the side of the triangle's plane (+1 along (b − a) × (c − a), −1
  // against) the node came from, kept while the pair touches (0 for a bar–bar pair).
  std::int8_t side = 0;
};

// A pair near enough to touch before any of its nodes has moved by the skin
// (contact_candidates.hpp).
struct ContactCandidate {
  std::uint64_t key = 0;
  std::array<Index, 4> nodes{};  // A's nodes, then B's, as in ContactPoint
};

struct ObjectContactWorkspace {
  std::vector<ContactCandidate> candidates;  // in the search's order, found at `reference_x`
  std::vector<Vec3> reference_x;             // (n_nodes) m, the positions they were found at
  bool candidates_found = false;
  double skin = 0.0;             // m, of the candidates found last (0: none yet)
  std::int64_t search_step = 0;  // the step they were found at
  std::int64_t searches = 0;     // how many times the candidates were found, in all
  // (n_threads) scratch: each thread's candidates and touching pairs, joined in thread order.
  std::vector<std::vector<ContactCandidate>> thread_candidates;
  std::vector<std::vector<ContactPoint>> thread_touching;
  std::vector<ContactPoint> touching;       // at the last force evaluation, by features
  std::vector<ContactPoint> previous;       // at the step before, by features (friction's history)
  std::vector<Box> bar_boxes;               // (n_bars) each bar's capsule box
  std::vector<Box> triangle_boxes;          // (n_triangles)
  std::vector<std::uint8_t> bar_used;       // (n_bars) 1 for an unbroken bar with contact
  // (n_objects) 1 where the object's bars look for pairs at all: it touches itself, or it is the
  // side that looks (bars_look_for, contact_candidates.cpp) for another object it may touch.
  std::vector<std::uint8_t> object_bars_look;
  std::vector<std::uint8_t> triangle_used;  // (n_triangles) 1 for a triangle of an unbroken face
  ContactGrid bar_grid;
  ContactGrid triangle_grid;
  double energy = 0.0;  // J, Σ ½ k δ² over `touching`
};

}  // namespace dinam
