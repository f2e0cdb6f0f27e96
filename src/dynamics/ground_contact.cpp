#include "dynamics/ground_contact.hpp"

#include <algorithm>

#include "model/model.hpp"

namespace dinam {

ContactForces ground_contact(const GroundContact& ground, double stiffness, double damping,
                             const Vec3& x, const Vec3& v, const Vec3& anchor, bool sliding) {
  ContactForces result;
  const Vec3& n = ground.normal;
  const double distance = (x - ground.point).dot(n);
  const double penetration = -distance;
  const double elastic = stiffness * penetration;
  const double normal_force = std::max(0.0, elastic - damping * v.dot(n));
  result.normal_elastic = elastic * n;
  result.normal_damping = (normal_force - elastic) * n;
  result.energy = 0.5 * elastic * penetration;

  // Tangential: the stick spring from the anchor to the node's foot on the plane, with the same
  // damper as the normal direction, so that landing on a slope loads both directions alike.
  const Vec3 foot = x + penetration * n;
  const Vec3 tangential_velocity = v - v.dot(n) * n;
  const Vec3 trial = -stiffness * (foot - anchor) - damping * tangential_velocity;
  const double trial_norm = trial.norm();
  const double limit = (sliding ? ground.kinetic_friction : ground.static_friction) * normal_force;
  if (ground.stick || trial_norm <= limit) {
    result.friction = trial;
    result.anchor = anchor;
    result.sliding = false;
  } else {
    const double kinetic = ground.kinetic_friction * normal_force;
    result.friction = (kinetic / trial_norm) * trial;
    result.anchor = foot + result.friction / stiffness;  // dragged along, at the kinetic force
    result.sliding = true;
  }
  return result;
}

void add_ground_contact_forces(ForceContext& context, std::vector<Vec3>* damping_ledger,
                               std::vector<Vec3>* friction_ledger) {
  const Model& model = context.model;
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  State& state = context.state;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double distance = (state.x[i] - ground.point).dot(ground.normal);
    if (distance >= 0.0 || model.pinned(i)) {
      if (context.update_history) {
        state.contact_touching[i] = 0;
        state.contact_sliding[i] = 0;
      }
      continue;
    }
    // A node that has just touched is anchored at its foot on the plane.
    const Vec3 anchor = state.contact_touching[i] != 0
                            ? state.contact_anchor[i]
                            : Vec3(state.x[i] - distance * ground.normal);
    const ContactForces f =
        ground_contact(ground, ground.node_stiffness[i], ground.node_damping[i], state.x[i],
                       state.v_half[i], anchor, state.contact_sliding[i] != 0);
    context.force[i] += f.normal_elastic;
    context.force[i] += f.normal_damping;
    context.force[i] += f.friction;
    if (damping_ledger != nullptr) {
      (*damping_ledger)[i] += f.normal_damping;
      (*friction_ledger)[i] += f.friction;
    }
    if (context.update_history) {
      state.contact_touching[i] = 1;
      state.contact_anchor[i] = f.anchor;
      state.contact_sliding[i] = f.sliding ? 1 : 0;
    }
  }
}

double ground_contact_energy(const Model& model, const State& state) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return 0.0;
  }
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double penetration = -(state.x[i] - ground.point).dot(ground.normal);
    if (penetration > 0.0 && !model.pinned(i)) {
      energy += 0.5 * ground.node_stiffness[i] * penetration * penetration;
    }
  }
  return energy;
}

}  // namespace dinam
