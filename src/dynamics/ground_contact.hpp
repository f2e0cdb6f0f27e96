#pragma once
// Impact on a rigid ground: a half-space behind a plane (point p, outward unit normal n).
//
// Normal: a node at signed distance d = (x − p)·n < 0 is pushed out by the penalty k (−d) and
// damped by −c (v·n); the sum is clipped at zero, so the ground only ever pushes. Because the
// ground is a half-space, not a sheet, a node can never pass through it however fast it hits:
// it is pushed back for as long as it is below.
//
// Tangential: Coulomb friction regularised by a stick spring. On touching, a node is anchored
// where it meets the plane; the trial force −k (x_t − anchor) − c v_t (the same k and c as the
// normal direction, so a block landing on a slope loads both in proportion) holds it while
// |F_t| ≤ μs N
// (sticking: it moves only by the spring's elastic give, |F_t|/k). Beyond that it slides, with
// the force μk N against the trial direction and the anchor dragged along, until the trial
// force falls back to μk N. With `stick` it never slides (the paper's falling ball).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/stiffness.hpp"
#include "model/model.hpp"

namespace dinam {

struct ContactForces {
  Vec3 normal_elastic = Vec3::Zero();  // N, k (−d) n
  Vec3 normal_damping = Vec3::Zero();  // N, what the damper adds (after the clip at zero)
  Vec3 friction = Vec3::Zero();        // N, tangential
  Vec3 anchor = Vec3::Zero();          // the stick anchor after this evaluation
  bool sliding = false;
  double energy = 0.0;  // J, ½ k d²
};

// One node below the plane. `anchor` and `sliding` are its history from the last step.
// Selects rather than branches, and dot3 rather than Eigen's dot, so that the loop over the nodes
// vectorises (ground_contact.cpp).
[[gnu::always_inline]] inline ContactForces ground_contact(const GroundContact& ground,
                                                           double stiffness, double damping,
                                                           const Vec3& x, const Vec3& v,
                                                           const Vec3& anchor, bool sliding) {
  ContactForces result;
  const Vec3& n = ground.normal;
  const double distance = dot3(x - ground.point, n);
  const double penetration = -distance;
  const double elastic = stiffness * penetration;
  const double normal_force = std::max(0.0, elastic - damping * dot3(v, n));
  result.normal_elastic = elastic * n;
  result.normal_damping = (normal_force - elastic) * n;
  result.energy = 0.5 * elastic * penetration;

  // Tangential: the stick spring from the anchor to the node's foot on the plane, with the same
  // damper as the normal direction, so that landing on a slope loads both directions alike.
  const Vec3 foot = x + penetration * n;
  const Vec3 tangential_velocity = v - dot3(v, n) * n;
  const Vec3 trial = -stiffness * (foot - anchor) - damping * tangential_velocity;
  const double trial_norm = norm3(trial);
  const double limit = (sliding ? ground.kinetic_friction : ground.static_friction) * normal_force;
  // Sticking, or sliding at the kinetic force with the anchor dragged along (trial_norm > limit
  // ≥ 0 there, so the quotient is safe where it is used).
  const bool sticks = ground.stick || trial_norm <= limit;
  const double kinetic = ground.kinetic_friction * normal_force;
  const Vec3 slide = (kinetic / (sticks ? 1.0 : trial_norm)) * trial;
  const Vec3 dragged = foot + slide / stiffness;
  for (int c = 0; c < 3; ++c) {
    result.friction[c] = sticks ? trial[c] : slide[c];
    result.anchor[c] = sticks ? anchor[c] : dragged[c];
  }
  result.sliding = !sticks;
  return result;
}

// Adds the contact forces of every free node below the plane to context.force, on the context
// worker's own nodes (parallel_loops.hpp): the elastic push, the normal damping and the friction,
// in that order. While the energy is tracked the
// damping and the friction also go to their ledgers (both given or both null).
void add_ground_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger = nullptr,
                               std::vector<Vec3>* friction_ledger = nullptr);

double ground_contact_energy(const Model& model, const State& state);  // Σ ½ k d², J

// Every free node below the plane marked touching and sticking, its stick spring anchored at its
// foot on the plane (so unstretched): the contact history of a static equilibrium found without
// stepping, from which the motion then starts as from one it had come to rest in.
void anchor_nodes_at_rest(const Model& model, State& state);

// The stiffness of the normal penalty, k n nᵀ on each free node below the plane (stiffness.hpp).
// Friction's stick spring is left out: it pulls towards an anchor that the motion's history
// placed, which is no potential of the positions.
void add_ground_contact_stiffness(const Model& model, const State& state, StiffnessSink& sink);

}  // namespace dinam
