#pragma once
// Contact between objects and within one (model.contact): bars are capsules of a contact radius,
// faces (fanned into triangles) thin shells of one, and two of them touch when the closest points
// of their middles are nearer than the sum of their radii. Two kinds of pair cover every way one
// can pass through another: bar–bar (the closest points of two segments, which also covers a
// node against a bar, at a segment's end) and node–triangle. Pairs that share a node never touch;
// nor do two objects unless both take part in contact between objects, nor an object with itself
// unless it takes part in self-contact; nor two primitives with no free node between them.
//
// Normal: at penetration δ = r_A + r_B − |p_A − p_B| the penalty k δ pushes the closest points
// apart along n = (p_A − p_B)/|p_A − p_B|, damped by −c (v_rel·n) and clipped at zero, so contact
// only pushes. k = ω_c² / (1/m_A + 1/m_B), with m_X the lightest free node of primitive X, so
// that no contact oscillates faster than ω_c whatever the masses (auto), or the scene's stiffness;
// c = 2 ζ √(k m), m = 1 / Σ w_j²/m_j the mass the contact point moves (a rigid bar struck at its
// middle: the bar's mass), so that ζ is the contact's damping ratio.
//
// Tangential: Coulomb friction with a stick spring, as the ground's: the pair's relative
// tangential motion since it touched stretches a spring of the same k; it holds while
// |F_t| ≤ μs N and beyond that slides at μk N, the spring's stretch set to what that force needs.
//
// Every force acts at the closest points and is shared out to the primitives' nodes by the
// points' weights, equal and opposite on the two sides, so momentum is conserved. Pairs that name
// the same features (a node over a vertex where six triangles meet) are one contact
// (contact_pairs.hpp finds them); contacts are summed in the order of their features, so the
// motion does not depend on the thread count. Within the envelope
// (relative speed × Δt below the smaller radius) no primitive passes through another; beyond it
// a node can cross a shell's middle in one step, and is then pushed back to the side it came
// from (ContactPoint::side), which holds as long as the penalty stops it within the shell.
#include <array>
#include <cstdint>
#include <vector>

#include "dynamics/force_context.hpp"
#include "dynamics/stiffness.hpp"

namespace dinam {

struct ContactPoint;

// A pair's normal penalty: `soft` N/m up to a penetration `knee`, `stiff` beyond (the automatic
// stiffness; a given one is linear, its knee infinite).
struct ContactPenalty {
  double soft = 0.0;   // N/m
  double stiff = 0.0;  // N/m
  double knee = 0.0;   // m

  double force(double penetration) const;   // N, pushing the pair apart
  double energy(double penetration) const;  // J
  double slope(double penetration) const;   // N/m, d force / d penetration
};

// The penalty of a pair of reach `reach` whose sides' lightest free nodes have inverse masses
// `inverse_a` and `inverse_b` (1/kg; 0 for a side all pinned): the automatic stiffness (the
// header's), or the scene's.
ContactPenalty contact_penalty_between(const Model& model, double inverse_a, double inverse_b,
                                       double reach);

// A touching pair's normal penalty at positions x (its separation and weights found there): the
// direction it pushes side A along, how deep the pair is, the penalty's force along that
// direction and its energy, and the soft stiffness its damper and friction take. A node–triangle
// pair's node is pushed back to `point.side` of the triangle's plane.
struct ContactPush {
  ContactPenalty penalty;
  Vec3 normal = Vec3::Zero();
  double penetration = 0.0;     // m
  double force = 0.0;           // N
  double energy = 0.0;          // J
  double soft_stiffness = 0.0;  // N/m
};
ContactPush contact_push(const Model& model, const ContactPoint& point, const std::vector<Vec3>& x);

// The side of the plane of triangle (at[1], at[2], at[3]) that node at[0] is on: +1 along
// (at[2] − at[1]) × (at[3] − at[1]) or in the plane, −1 against.
std::int8_t triangle_side(const std::array<Vec3, 4>& at);

// Adds the contact forces between objects and within them to context.force; while the energy
// is tracked, the normal damping and the friction also go to their ledgers (both or neither).
// The friction's stick springs stretch by the relative velocity times state.dt.
void add_object_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger = nullptr,
                               std::vector<Vec3>* friction_ledger = nullptr);

// Σ ½ k δ² over the pairs touching at the last force evaluation, J.
double object_contact_energy(const State& state);

// The stiffness of the normal penalty of each pair touching at the last force evaluation
// (stiffness.hpp), over its four nodes: the Jacobian of k δ n shared out by the closest points'
// weights, the weights' own motion with the nodes included. Friction's stick springs and the
// dampers are left out (history and velocity, not potentials of the positions).
void add_object_contact_stiffness(const Model& model, const State& state, StiffnessSink& sink);

}  // namespace dinam
