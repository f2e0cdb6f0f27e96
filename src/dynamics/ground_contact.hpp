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
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

struct GroundContact;

struct ContactForces {
  Vec3 normal_elastic = Vec3::Zero();  // N, k (−d) n
  Vec3 normal_damping = Vec3::Zero();  // N, what the damper adds (after the clip at zero)
  Vec3 friction = Vec3::Zero();        // N, tangential
  Vec3 anchor = Vec3::Zero();          // the stick anchor after this evaluation
  bool sliding = false;
  double energy = 0.0;  // J, ½ k d²
};

// One node below the plane. `anchor` and `sliding` are its history from the last step.
ContactForces ground_contact(const GroundContact& ground, double stiffness, double damping,
                             const Vec3& x, const Vec3& v, const Vec3& anchor, bool sliding);

// Adds the contact forces of every free node below the plane to context.force: the elastic
// push, the normal damping and the friction, in that order. While the energy is tracked the
// damping and the friction also go to their ledgers (both given or both null).
void add_ground_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger = nullptr,
                               std::vector<Vec3>* friction_ledger = nullptr);

double ground_contact_energy(const Model& model, const State& state);  // Σ ½ k d², J

}  // namespace dinam
