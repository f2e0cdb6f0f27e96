#include "dynamics/integrator.hpp"

#include <cmath>

#include "core/error.hpp"
#include "dynamics/axial_spring.hpp"
#include "dynamics/field_forces.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Pinned nodes are skipped: they cannot diverge by themselves (only through 0 × ∞ once a
// neighbour's force has overflowed), and naming the free node that did is what helps the user.
void check_finite(const Model& model, const State& state) {
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.pinned(i)) {
      continue;
    }
    if (!state.x[i].allFinite() || !state.v_half[i].allFinite()) {
      throw RuntimeError(fmt::format(
          "the simulation diverged: node {} of object '{}' has a non-finite position or velocity "
          "at step {} (t = {:.6g} s). The time step is too long for the forces at work; use "
          "'timestep: auto' or a shorter step",
          i, model.objects[model.node_object[i]].name, state.step, state.time));
    }
  }
}

}  // namespace

void compute_forces(const Model& model, const ForceSwitches& switches, State& state) {
  // 1. Clear.
  for (Vec3& f : state.force) {
    f.setZero();
  }
  // 2. External field forces.
  if (switches.gravity) {
    add_gravity_forces(model, state.force);
  }
  // 3. Internal elastic forces.
  if (switches.axial_springs) {
    add_axial_spring_forces(model, state.x, state.force);
  }
}

State initial_state(const Model& model, double dt, const ForceSwitches& switches) {
  State state;
  state.x = model.node_initial_x;
  state.v_half = model.node_initial_v;
  state.force.assign(model.node_count(), Vec3::Zero());
  compute_forces(model, switches, state);
  for (Index i = 0; i < model.node_count(); ++i) {
    state.v_half[i] -= 0.5 * dt * model.node_inv_mass[i] * state.force[i];
  }
  return state;
}

void step(const Model& model, double dt, const ForceSwitches& switches, State& state) {
  compute_forces(model, switches, state);
  // Integrate. Pinned nodes have zero inverse mass and zero velocity, so they stay put.
  const Index n = model.node_count();
  for (Index i = 0; i < n; ++i) {
    state.v_half[i] += (dt * model.node_inv_mass[i]) * state.force[i];
    state.x[i] += dt * state.v_half[i];
  }
  state.step += 1;
  state.time = static_cast<double>(state.step) * dt;
  check_finite(model, state);
}

}  // namespace dinam
