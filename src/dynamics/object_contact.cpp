#include "dynamics/object_contact.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_pairs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// The direction to push A along when the closest points coincide: across both bars, or along
// the triangle's normal.
Vec3 fallback_normal(const ContactPoint& point, const std::vector<Vec3>& x) {
  const std::array<Index, 4>& n = point.nodes;
  const Vec3 normal = (point.key >> 63) == kBarBarContact
                          ? Vec3((x[n[1]] - x[n[0]]).cross(x[n[3]] - x[n[2]]))
                          : Vec3((x[n[2]] - x[n[1]]).cross(x[n[3]] - x[n[1]]));
  return normal.squaredNorm() > 0.0 ? normal.normalized() : kWorldUp;
}

}  // namespace

void add_object_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger,
                               std::vector<Vec3>* friction_ledger) {
  const Model& model = context.model;
  const ObjectContact& contact = model.contact;
  if (!contact.enabled) {
    return;
  }
  State& state = context.state;
  ObjectContactWorkspace& work = state.object_contact;
  find_touching_pairs(model, state);

  work.energy = 0.0;
  auto previous = work.previous.begin();
  for (ContactPoint& point : work.touching) {
    while (previous != work.previous.end() && previous->features < point.features) {
      ++previous;
    }
    const bool touched_before =
        previous != work.previous.end() && previous->features == point.features;
    const bool bar_pair = (point.key >> 63) == kBarBarContact;
    const int side_a_nodes = bar_pair ? 2 : 1;  // the nodes before are A's, the rest B's
    // The lightest free node on each side sets the pair's stiffness (see the header).
    // The damper acts on the mass the contact point moves, m = 1 / Σ w_j²/m_j.
    double inverse_a = 0.0;
    double inverse_b = 0.0;
    double inverse_moved = 0.0;
    Vec3 relative_velocity = Vec3::Zero();
    for (int j = 0; j < 4; ++j) {
      const double inverse_mass = model.node_inv_mass[point.nodes[j]];
      double& inverse = j < side_a_nodes ? inverse_a : inverse_b;
      inverse = std::max(inverse, inverse_mass);
      inverse_moved += point.weights[j] * point.weights[j] * inverse_mass;
      relative_velocity += point.weights[j] * state.v_half[point.nodes[j]];
    }
    const double k = contact.omega_squared > 0.0 ? contact.omega_squared / (inverse_a + inverse_b)
                                                 : contact.stiffness;
    const double c =
        inverse_moved > 0.0 ? 2.0 * contact.damping_ratio * std::sqrt(k / inverse_moved) : 0.0;

    const double distance = point.separation.norm();
    const double reach = contact_reach(contact, point.key);
    const Vec3 normal = distance > 1e-12 * reach ? Vec3(point.separation / distance)
                                                 : fallback_normal(point, state.x);
    const double penetration = reach - distance;
    const double elastic = k * penetration;
    const double normal_force = std::max(0.0, elastic - c * relative_velocity.dot(normal));
    point.energy = 0.5 * elastic * penetration;
    work.energy += point.energy;

    // Friction: the stick spring stretches with the relative tangential motion since the pair
    // touched, kept in the current tangent plane.
    const Vec3 tangential_velocity = relative_velocity - relative_velocity.dot(normal) * normal;
    Vec3 slip = touched_before ? previous->slip : Vec3::Zero();
    slip += work.dt * tangential_velocity;
    slip -= slip.dot(normal) * normal;
    const Vec3 trial = -k * slip - c * tangential_velocity;
    const double trial_norm = trial.norm();
    const bool was_sliding = touched_before && previous->sliding;
    const double limit =
        (was_sliding ? contact.kinetic_friction : contact.static_friction) * normal_force;
    Vec3 friction = trial;
    point.sliding = false;
    if (trial_norm > limit) {
      friction = (contact.kinetic_friction * normal_force / trial_norm) * trial;
      slip = -friction / k;
      // A pair that touches without pressing (N = 0) holds nothing, but does not slide either:
      // the next step, pressing, it sticks up to μs N again.
      point.sliding = normal_force > 0.0;
    }
    point.slip = slip;

    const Vec3 damping = (normal_force - elastic) * normal;
    const Vec3 on_a = elastic * normal + damping + friction;
    for (int j = 0; j < 4; ++j) {
      const double w = point.weights[j];
      context.force[point.nodes[j]] += w * on_a;
      if (damping_ledger != nullptr) {
        (*damping_ledger)[point.nodes[j]] += w * damping;
        (*friction_ledger)[point.nodes[j]] += w * friction;
      }
    }
  }
  if (context.update_history) {
    std::swap(work.touching, work.previous);
  }
}

double object_contact_energy(const State& state) {
  return state.object_contact.energy;
}

}  // namespace dinam
