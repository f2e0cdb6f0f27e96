#pragma once
// What contact between objects keeps from step to step (the friction's stick springs) and the
// broad phase's arrays, reused so that a step allocates nothing once they have grown.
#include <array>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/contact_grid.hpp"

namespace dinam {

// One touching pair: side A (a bar, or a node) against side B (a bar, or a triangle).
struct ContactPoint {
  std::uint64_t key = 0;  // kind, A's id, B's id: contacts are summed and matched in this order
  std::array<Index, 4> nodes{};     // A's nodes, then B's (a node–triangle pair: 1 + 3)
  std::array<double, 4> weights{};  // the closest points' weights, A's ≥ 0, B's ≤ 0 (negated)
  Vec3 separation = Vec3::Zero();   // m, p_A − p_B between the closest points
  Vec3 slip = Vec3::Zero();         // m, the stick spring's tangential stretch
  double energy = 0.0;              // J, ½ k δ² of the normal penalty
  bool sliding = false;
};

struct ObjectContactWorkspace {
  std::vector<ContactPoint> touching;       // at the last force evaluation, by key
  std::vector<ContactPoint> previous;       // at the step before, by key (the friction's history)
  std::vector<Box> bar_boxes;               // (n_bars) each bar's capsule box
  std::vector<Box> triangle_boxes;          // (n_triangles)
  std::vector<std::uint8_t> bar_used;       // (n_bars) 1 for an unbroken bar with contact
  std::vector<std::uint8_t> triangle_used;  // (n_triangles) 1 for a triangle of an unbroken face
  ContactGrid bar_grid;
  ContactGrid triangle_grid;
  double energy = 0.0;  // J, Σ ½ k δ² over `touching`
  double dt = 0.0;      // s, the step the integrator takes (set by it)
};

}  // namespace dinam
