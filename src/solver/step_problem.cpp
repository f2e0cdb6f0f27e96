#include "solver/step_problem.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "dynamics/contact/ground_restitution.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/tearing.hpp"
#include "dynamics/tie_springs.hpp"
#include "model/model.hpp"
#include "solver/potential.hpp"
#include "solver/step_scheme.hpp"

namespace dinam {
namespace {

// The springs alone, whose plastic sets a step's end moves on.
ForceSwitches spring_switches() {
  ForceSwitches switches = ForceSwitches::none();
  for (const ForceKind* kind : kForceKinds) {
    switches.*kind->switched = kind->spring != nullptr;
  }
  return switches;
}

}  // namespace

StepProblem::StepProblem(const Model& model, const StepScheme& scheme)
    : dofs(free_dofs(model)),
      mass(free_masses(model, dofs)),
      envelope(contact_envelope(model)),
      any_yield(std::any_of(kSpringKinds.begin(), kSpringKinds.end(),
                            [&](const SpringKind* kind) { return kind->yields(model); })),
      potential{dofs, mass, scheme.x_start, friction, objects} {}

void StepProblem::break_bars(const Model& model, State& state) const {
  if (model.can_tear()) {
    break_overloaded_bars(model, state);
  }
  break_overloaded_ties(model, state);
}

void StepProblem::take_loads(const Model& model, State& state, double t_next) {
  const std::size_t n = state.x.size();
  loads.assign(n, Vec3::Zero());
  for (std::size_t k = 0; k < kForceKinds.size(); ++k) {
    const ForceKind& kind = *kForceKinds[k];
    const bool at_end = kind.implicit == ImplicitTreatment::kLoadAtEnd;
    if ((!at_end && kind.implicit != ImplicitTreatment::kLoadAtStart) ||
        !kind.acts_in(model, ForceSwitches{})) {
      continue;
    }
    compute_forces_at(model, only(kind), state, at_end ? t_next : state.time);
    for (std::size_t i = 0; i < n; ++i) {
      loads[i] += state.force[i];
    }
    if (state.energy_workspace.enabled) {
      load_forces[k] = state.force;
    }
  }
}

void StepProblem::start_contact(const Model& model, State& state, const StepScheme& scheme) {
  // (Central differences' own friction is no potential: the step's potential forces leave it
  // out.)
  friction.start_step(model, state);
  objects.start_step(model, state);
  if (state.energy_workspace.enabled) {
    potential_at_start_ =
        potential_energy(model, state, potential.switches, scheme.x_start, SpringEnergy::kWithFlow)
            .energy;
  }
}

void StepProblem::set_potential(const Model& model, State& state, const StepScheme& scheme) {
  potential.model = &model;
  potential.state = &state;
  potential.hs = scheme.hs;
  potential.alpha = 0.0;
  damper_triplets_.clear();
  potential.pinned_damping.setZero(dofs.count);
  for (const ForceKind* kind : kForceKinds) {
    const ImplicitDamper& damper = kind->damper;
    if (kind->implicit != ImplicitTreatment::kDamper || !kind->acts_in(model, ForceSwitches{})) {
      continue;
    }
    if (damper.mass_rate != nullptr) {
      potential.alpha += damper.mass_rate(model);
    }
    if (damper.add_hessian != nullptr) {
      damper.add_hessian(model, state, dofs, scheme.x_start, scheme.hs, damper_triplets_);
    }
    if (damper.add_support_pull != nullptr) {
      damper.add_support_pull(model, state, dofs, scheme.x_start, scheme.x_base, scheme.hs,
                              potential.pinned_damping);
    }
  }
  potential.damping = &dampers.set(dofs.count, damper_triplets_);
  potential.inertia = mass / (scheme.hs * scheme.hs) + (potential.alpha / scheme.hs) * mass;
  free_part(dofs, predicted, potential.predicted);
  free_part(dofs, scheme.x_base, potential.start);
}

bool StepProblem::past_envelope(const Model& model, const std::vector<Vec3>& x) {
  return model.contact.enabled && objects.longest_move(model, x) > envelope;
}

void StepProblem::place_start(State& state, const StepScheme& scheme) {
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    if (dofs.first_dof[i] >= 0) {
      state.x[i] = predicted[i];
    }
  }
  if (!rebounded) {
    return;
  }
  const double at_prediction = potential.energy();
  unbounced_start_.assign(state.x.begin(), state.x.end());
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    if (dofs.first_dof[i] >= 0) {
      unbounced_start_[i] += scheme.hs * (v_unbounced_[i] - scheme.v_base[i]);
    }
  }
  std::swap(state.x, unbounced_start_);
  if (potential.energy() >= at_prediction) {
    std::swap(state.x, unbounced_start_);
  }
}

const ImplicitStepEnds* StepProblem::measure_ends(const Model& model, State& state,
                                                  const StepScheme& scheme) {
  if (!state.energy_workspace.enabled) {
    return nullptr;
  }
  const std::vector<Vec3>& x_start = scheme.x_start;
  ImplicitStepEnds& measured = step_ends_;
  auto step_potential = [&] {  // P and its friction springs' share, at state.x
    const double ground_friction = friction.energy(state.x);
    return std::pair{
        potential_energy(model, state, potential.switches, x_start, SpringEnergy::kWithFlow)
                .energy +
            ground_friction + objects.energy(model, state),
        ground_friction + objects.friction_energy(state.x)};
  };
  potential.gradient(gradient_);  // leaves the potential's forces at x_{n+1} in state.force
  free_part(dofs, state.force, measured.potential_force);
  measured.support_work = 0.0;
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    if (dofs.first_dof[i] < 0) {  // a pinned node: its support's work
      measured.support_work += state.force[i].dot(x_start[i] - state.x[i]);
    }
  }
  std::tie(measured.potential_end, measured.friction_end) = step_potential();
  const double ground_friction_start = friction.energy(x_start);
  measured.potential_start =
      potential_at_start_ + ground_friction_start + objects.energy_at_start(model);
  measured.friction_start = ground_friction_start + objects.friction_energy(x_start);
  measured.mass = mass;
  free_part(dofs, x_start, measured.x_start);
  free_part(dofs, scheme.v_start, measured.v_start);
  measured.x_base = potential.start;
  free_part(dofs, scheme.v_base, measured.v_base);
  free_part(dofs, state.x, measured.x_end);
  potential.moved = measured.x_end - potential.start;
  const Eigen::VectorXd& moved = potential.moved;
  measured.v_end = moved / scheme.hs;
  potential.damped.noalias() = *potential.damping * moved;
  measured.damper_force = -(potential.alpha / scheme.hs) * mass.cwiseProduct(moved) -
                          potential.damped + potential.pinned_damping;
  std::size_t kept = 0;
  for (std::size_t k = 0; k < kForceKinds.size(); ++k) {
    if (!load_forces[k].empty()) {
      if (kept == measured.loads.size()) {
        measured.loads.emplace_back();
      }
      ImplicitStepEnds::Load& load = measured.loads[kept++];
      load.work = kForceKinds[k]->ledger[0].work;
      free_part(dofs, load_forces[k], load.force);
    }
  }
  measured.loads.resize(kept);
  return &measured;
}

bool StepProblem::find_contact_change(const Model& model, State& state,
                                      const std::vector<Vec3>& x_start) {
  contact_changed = false;
  if (model.ground.enabled) {
    for (std::size_t i = 0; i < state.x.size() && !contact_changed; ++i) {
      const auto node = static_cast<Index>(i);
      contact_changed = (model.ground.clearance(node, x_start[i]) < 0.0) !=
                        (model.ground.clearance(node, state.x[i]) < 0.0);
    }
  }
  contact_changed = objects.touching_changed(model, state) || contact_changed;
  return contact_changed;
}

void StepProblem::book_and_rebound(const Model& model, State& state, const StepScheme& scheme,
                                   const ImplicitStepEnds* ends) {
  if (ends) {
    const EnergyAccounts step = implicit_step_accounts(*ends);
    state.energy.add_works(step, 1.0);
    state.energy.numerical_dissipation += step.numerical_dissipation;
  }
  const double kinetic_before = ends ? kinetic_energy(model, state.velocity) : 0.0;
  v_unbounced_ = state.velocity;
  const bool landed = rebound_landing_nodes(model, scheme.x_start, scheme.v_start, state);
  rebounded = objects.rebound_pairs(model, scheme.v_start, scheme.h, state) || landed;
  if (ends) {
    state.energy.numerical_dissipation -= kinetic_energy(model, state.velocity) - kinetic_before;
  }
  friction.finish_step(model, state);
  objects.finish_step(model, scheme.h, state);
  if (any_yield) {
    compute_forces(model, spring_switches(), state, true);
  }
}

}  // namespace dinam
