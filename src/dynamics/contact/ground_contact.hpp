#pragma once
// Impact on a rigid ground: a half-space behind a plane (point p, outward unit normal n).
//
// Normal: a node at signed distance d = (x − p)·n < 0 is pushed out by the penalty k (−d) and
// damped by −c v_n·n; the sum is clipped at zero, so the ground only ever pushes. Because the
// ground is a half-space, not a sheet, a node can never pass through it however fast it hits:
// it is pushed back for as long as it is below.
//
// The damper is where central differences lose the spring–dashpot's restitution: it switches on
// at full strength the instant a node crosses the plane, and it would act on v_{n−½}, half a step
// late. So it acts on the velocity at t_n, v_n = v_{n−½} + Δt/2m (F_other + F_ground) with every
// other force on the node and its own push solved for (implicit in itself, for one node:
// N = (k(−d) − c v*)/(1 + cΔt/2m), v* the velocity at t_n without the ground); and in the step a
// node first touches, c is scaled by (τ + Δt/2)/Δt, τ = −d / (−v·n) the time since it crossed,
// the damper's share of that step. The rebound then keeps the closed form's restitution to 2 %
// at the automatic stiffness (contact_builder.cpp), and at rest v_n = 0 exactly.
//
// Tangential: Coulomb friction regularised by a stick spring. On touching, a node is anchored
// where it meets the plane; the trial force −k (x_t − anchor) − c v_t (the same k and c as the
// normal direction, v_t at n − ½) holds it while |F_t| ≤ μs N
// (sticking: it moves only by the spring's elastic give, |F_t|/k). Beyond that it slides, with
// the force μk N against the trial direction and the anchor dragged along, until the trial
// force falls back to μk N. A node that touches without pressing (N = 0, lifting off) holds
// nothing and is not marked sliding: pressed again, it sticks up to μs N. With `stick` it never
// slides (the paper's falling ball).
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

// One node below the plane. `anchor` and `sliding` are its history from the last step;
// `damping` is its damper's c (scaled for a first touch), `normal_speed` v*·n (the velocity at
// t_n without the ground, along n) and `implicit` 1 / (1 + cΔt/2m).
// Selects rather than branches, and dot3 rather than Eigen's dot, so that the loop over the nodes
// vectorises (ground_contact.cpp).
[[gnu::always_inline]] inline ContactForces ground_contact(const GroundContact& ground,
                                                           double stiffness, double damping,
                                                           double normal_speed, double implicit,
                                                           const Vec3& x, const Vec3& v,
                                                           const Vec3& anchor, bool sliding) {
  ContactForces result;
  const Vec3& n = ground.normal;
  const double distance = dot3(x - ground.point, n);
  const double penetration = -distance;
  const double elastic = stiffness * penetration;
  const double normal_force = std::max(0.0, (elastic - damping * normal_speed) * implicit);
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
  result.sliding = !sticks && normal_force > 0.0;
  return result;
}

// Adds the contact forces of every free node below the plane to context.force, on the context
// worker's own nodes (parallel_loops.hpp): the elastic push, the normal damping and the friction,
// in that order, after every other force of the team's (their sum sets v*). While the energy is
// tracked the
// damping and the friction also go to their ledgers (both given or both null).
void add_ground_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger = nullptr,
                               std::vector<Vec3>* friction_ledger = nullptr);

// The elastic push alone, k (−d) n on every free node below the plane (the same bits as above's
// first term): the ground's share of −∇V. Reads no velocity and no contact history.
void add_ground_penalty_forces(ForceContext& context);

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
