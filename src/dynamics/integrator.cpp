#include "dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/clamp_spring.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/field_forces.hpp"
#include "dynamics/global_damping.hpp"
#include "dynamics/ground_contact.hpp"
#include "dynamics/object_contact.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/settle.hpp"
#include "dynamics/tearing.hpp"
#include "dynamics/torsion_spring.hpp"
#include "dynamics/wind.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Pinned nodes are skipped: they cannot diverge by themselves (only through 0 × ∞ once a
// neighbour's force has overflowed), and naming the free node that did is what helps the user.
bool diverged(const Model& model, const State& state, Index i) {
  return !model.pinned(i) && !(state.x[i].allFinite() && state.v_half[i].allFinite());
}

[[noreturn]] void report_divergence(const Model& model, const State& state) {
  Index i = 0;
  while (!diverged(model, state, i)) {
    ++i;
  }
  throw RuntimeError(fmt::format(
      "the simulation diverged: node {} of object '{}' has a non-finite position or velocity "
      "at step {} (t = {:.6g} s). The time step is too long for the forces at work; use "
      "'timestep: auto' or a shorter step",
      i, model.objects[model.node_object[i]].name, state.step, state.time));
}

void clear(std::vector<Vec3>& forces) {
  for_each_index(static_cast<Index>(forces.size()), [&](Index i) { forces[i].setZero(); });
}

// Δt Σ F_i · v_i with the whole-step velocity v_n = ½ (v_{n−½} + v_{n+½}): the work of a force
// kind over the step around t_n. It is the trapezoid rule ½ (F_n + F_{n+1}) · Δx summed by parts,
// and pairs with the kinetic energy reported at whole steps; F_n · Δt v_{n+½} instead would book
// spurious work in modes that flip sign every step.
double work(const std::vector<Vec3>& force, const std::vector<Vec3>& v_whole, double dt) {
  double w = 0.0;
  for (std::size_t i = 0; i < force.size(); ++i) {
    w += force[i].dot(v_whole[i]);
  }
  return w * dt;
}

}  // namespace

void compute_forces(const Model& model, const ForceSwitches& switches, State& state,
                    bool update_history) {
  // Every kind adds to the total in this fixed order. While the energy is tracked, the
  // dissipative and driving kinds also keep their own forces in the ledger's arrays, for the
  // work they do; that does not change the order of the total's sums.
  EnergyWorkspace& ledger = state.energy_workspace;
  auto kind = [&](std::vector<Vec3>& part) {
    return ForceContext{model, state, state.force, update_history,
                        ledger.enabled ? &part : nullptr};
  };
  clear(state.force);
  if (ledger.enabled) {
    for (std::vector<Vec3>* part : ledger.force_parts()) {
      clear(*part);
    }
  }
  ForceContext total{model, state, state.force, update_history};

  // 1. External fields: gravity (a potential) and the scene's fields at t_n.
  if (switches.gravity) {
    add_gravity_forces(total);
  }
  if (switches.fields) {
    ForceContext fields = kind(ledger.field);
    add_field_forces(fields);
  }
  // 2. Aerodynamic drag.
  if (switches.wind) {
    ForceContext wind = kind(ledger.wind);
    add_wind_forces(wind);
  }
  // 3. Internal elastoplastic springs.
  if (switches.axial_springs) {
    add_axial_spring_forces(total);
  }
  if (switches.bending) {
    add_bending_spring_forces(total);
    add_clamp_forces(total);
  }
  if (switches.torsion) {
    add_torsion_spring_forces(total);
  }
  // 4. Viscous damping: axial dampers and global friction.
  ForceContext damping = kind(ledger.damping);
  if (switches.axial_dampers) {
    add_axial_damper_forces(damping);
  }
  if (switches.global_damping) {
    add_global_damping_forces(damping);
  }
  // 5. Boundary conditions: the ground, then contact between objects and within one.
  if (switches.ground) {
    add_ground_contact_forces(total, ledger.enabled ? &ledger.contact_damping : nullptr,
                              ledger.enabled ? &ledger.friction : nullptr);
  }
  if (switches.object_contact) {
    add_object_contact_forces(total, ledger.enabled ? &ledger.contact_damping : nullptr,
                              ledger.enabled ? &ledger.friction : nullptr);
  }
}

State initial_state(const Model& model, double dt, const ForceSwitches& switches,
                    bool track_energy) {
  const std::size_t n = model.node_count();
  State state;
  state.x = model.node_initial_x;
  state.v_half = model.node_initial_v;
  state.force.assign(n, Vec3::Zero());
  // Plastic sets only for the kinds that can yield (model.hpp).
  state.bar_plastic_set.assign(model.bar_colours.any_yield ? model.bar_count() : 0, 0.0);
  state.bend_plastic_set.assign(model.bend_colours.any_yield ? model.bend_count() : 0, 0.0);
  state.torsion_plastic_set.assign(model.torsion_colours.any_yield ? model.torsion_count() : 0,
                                   0.0);
  state.clamp_plastic_set.assign(model.clamp_count(), 0.0);
  // Scratch for the kinds that can yield, and contact history where there is a ground: an elastic
  // structure in the air carries neither (memory is part of speed for large models).
  Index yielding = 0;
  for (const SpringColouring* kind :
       {&model.bar_colours, &model.bend_colours, &model.torsion_colours}) {
    yielding = kind->any_yield ? std::max(yielding, kind->spring_count) : yielding;
  }
  state.plastic_flow.assign(
      static_cast<std::size_t>((yielding + kSpringBlockSize - 1) / kSpringBlockSize), 0.0);
  if (model.ground.enabled) {
    state.contact_anchor.assign(n, Vec3::Zero());
    state.contact_touching.assign(n, 0);
    state.contact_sliding.assign(n, 0);
  }
  prepare_tearing(model, state);
  prepare_wind(model, state);
  place_driven_nodes(model, 0.0, state);
  settle_under_gravity(model, dt, switches, state);
  EnergyWorkspace& ledger = state.energy_workspace;
  ledger.enabled = track_energy;
  if (track_energy) {  // the ledger's arrays exist only then (memory: 144 bytes per node)
    for (std::vector<Vec3>* part : ledger.force_parts()) {
      part->assign(n, Vec3::Zero());
    }
    ledger.v_previous.assign(n, Vec3::Zero());
  }
  state.object_contact.dt = dt;
  compute_forces(model, switches, state, false);
  if (track_energy) {  // after the forces: contact between objects finds its pairs there
    ledger.last = energy_report(model, state, state.v_half);
  }
  for (Index i = 0; i < model.node_count(); ++i) {
    state.v_half[i] -= 0.5 * dt * model.node_inv_mass[i] * state.force[i];
  }
  return state;
}

void step(const Model& model, double dt, const ForceSwitches& switches, State& state) {
  EnergyWorkspace& ledger = state.energy_workspace;
  // 0. Bars strained past their breaking limit at x_n break, with what stands on them.
  break_overloaded_bars(model, state);
  state.object_contact.dt = dt;
  // 1. Forces at (x_n, v_{n−½}, t_n); plastic sets and contact anchors move on.
  compute_forces(model, switches, state, true);
  if (ledger.enabled) {
    ledger.v_previous = state.v_half;
  }
  // 2. Velocities to n + ½. Pinned nodes have zero inverse mass and zero velocity.
  const Index n = model.node_count();
  for_each_index(
      n, [&](Index i) { state.v_half[i] += (dt * model.node_inv_mass[i]) * state.force[i]; });
  set_driven_velocities(model, static_cast<double>(state.step + 1) * dt, dt, state);
  // 3. Energy at t_n (velocities averaged across it), and the work of the forces around t_n:
  //    W_n = Δt F_n · v_n covers [t_n − Δt/2, t_n + Δt/2], so the report at t_n counts half of it.
  if (ledger.enabled) {
    for (Index i = 0; i < n; ++i) {
      ledger.v_previous[i] = 0.5 * (ledger.v_previous[i] + state.v_half[i]);
    }
    const std::vector<Vec3>& v_whole = ledger.v_previous;
    EnergyAccounts step_work;
    step_work.damping_work = work(ledger.damping, v_whole, dt);
    step_work.contact_damping_work = work(ledger.contact_damping, v_whole, dt);
    step_work.friction_work = work(ledger.friction, v_whole, dt);
    step_work.wind_work = work(ledger.wind, v_whole, dt);
    step_work.field_work = work(ledger.field, v_whole, dt);
    state.energy.add_works(step_work, 0.5);
    ledger.last = energy_report(model, state, v_whole);
    state.energy.add_works(step_work, 0.5);
  }
  // 4. Positions to n + 1, checked on the way.
  const bool any_diverged = any_index(n, [&](Index i) {
    state.x[i] += dt * state.v_half[i];
    return diverged(model, state, i);
  });
  state.step += 1;
  state.time = static_cast<double>(state.step) * dt;
  if (any_diverged) {
    report_divergence(model, state);
  }
}

}  // namespace dinam
