#include "solver/incremental_potential.hpp"

#include "dynamics/contact/ground_friction_implicit.hpp"
#include "dynamics/contact/object_contact_implicit.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/free_dofs.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "solver/potential.hpp"

namespace dinam {

ForceSwitches potential_switches() {
  return switches_treated_as(ImplicitTreatment::kInPotential);
}

void IncrementalPotential::gradient(Vector& g) const {
  compute_potential_forces(*model, switches, *state);
  friction.add_forces(state->x, state->force);
  objects.add_forces(*model, *state);
  free_part(dofs, state->x, x);
  moved = x - start;
  damped.noalias() = *damping * moved;
  free_part(dofs, state->force, forces);
  g = (mass / (hs * hs)).cwiseProduct(x - predicted) + (alpha / hs) * mass.cwiseProduct(moved) -
      forces + damped - pinned_damping;
}

double IncrementalPotential::energy() const {
  free_part(dofs, state->x, x);
  off = x - predicted;
  moved = x - start;
  damped.noalias() = *damping * moved;
  return potential_energy(*model, *state, switches, x_start, SpringEnergy::kWithFlow).energy +
         friction.energy(state->x) + objects.energy(*model, *state) +
         (0.5 / (hs * hs)) * mass.dot(off.cwiseProduct(off)) +
         (0.5 * alpha / hs) * mass.dot(moved.cwiseProduct(moved)) + 0.5 * moved.dot(damped) -
         pinned_damping.dot(moved);
}

}  // namespace dinam
