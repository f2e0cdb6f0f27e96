#pragma once
// Every kind of force, in the order a step adds them to each node's total (which is part of the
// motion's bits: each node sums its forces kind by kind in this order, whatever the threads). The
// explicit step, the potential and the stiffness Newton's method assembles, the implicit step's
// loads and switches, the energy report and its ledger, the memory estimate and the run-time
// estimate iterate this list (force_kind.hpp).
#include <array>
#include <stdexcept>
#include <string>

#include "dynamics/force_kind.hpp"
#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {

// Each entry sits in its kernel's file.
extern const ForceKind kGravity;        // field_forces.cpp
extern const ForceKind kFields;         // field_forces.cpp
extern const ForceKind kWind;           // wind.cpp
extern const ForceKind kGlobalDamping;  // global_damping.cpp
extern const ForceKind kAxialDampers;   // axial_spring.cpp
extern const ForceKind kGroundContact;  // ground_contact.cpp
extern const ForceKind kObjectContact;  // object_contact.cpp
extern const ForceKind kTies;           // tie_springs.cpp

// A spring kind (spring_kind.hpp) as a force kind: a potential, its plastic sets held.
// kHeld: whether `integrator: xpbd` holds it as a constraint (its SpringKind's constraint.held,
// which spring_kinds_test checks against this).
template <const SpringKind& kSpring, bool ForceSwitches::*kSwitch, bool kHeld = false>
inline constexpr ForceKind kSpringForces{
    .label = nullptr,
    .spring = &kSpring,
    .role = ForceRole::kPotential,
    .implicit = ImplicitTreatment::kInPotential,
    .damper = {},
    .switched = kSwitch,
    .present = nullptr,
    .prepare_forces = nullptr,
    .add_forces = [](ForceContext& total, const StepOptions&) { kSpring.add_forces(total); },
    .add_forces_after_team = nullptr,
    .add_potential =
        [](const Model& model, const State& state, const PotentialQuery& query,
           Potential& potential) { potential.add(kSpring.energy(model, state, query.springs)); },
    .add_stiffness = [](const Model& model, const State& state,
                        StiffnessSink& sink) { kSpring.add_stiffness(model, state, sink); },
    .report_energy =
        [](const Model& model, const State& state, EnergyReport& report) {
          report.*kSpring.report += kSpring.energy(model, state, SpringEnergy::kStored);
        },
    .ledger = {},
    // Its plastic sets where some can yield, and while the energy is tracked each one's flow
    // (make_state allocates them for every spring kind).
    .prepare_state = nullptr,
    .state_bytes = [](const Model& model, bool energy) -> std::uint64_t {
      const auto count = static_cast<std::uint64_t>(kSpring.count(model));
      return kSpring.yields(model) ? count * sizeof(double) * (energy ? 2 : 1) : 0;
    },
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          sink.add(kSpring.name(), static_cast<double>(kSpring.count(model)),
                   kSpring.yields(model) ? kSpring.ns_per_item_yielding : kSpring.ns_per_item);
        },
    // A spring kind held as a constraint has its projection (spring_kind.hpp).
    .constraint = {.held = kHeld,
                   .project =
                       [](const Model& model, double h, int sweep, State& state) {
                         kSpring.constraint.project(model, h, sweep, state);
                       },
                   .finish =
                       [](const Model& model, double h, State& state) {
                         if (kSpring.constraint.finish != nullptr) {
                           kSpring.constraint.finish(model, h, state);
                         }
                       },
                   .add_cost =
                       [](const Model& model, StepCostSink& sink) {
                         if (kSpring.constraint.add_cost != nullptr) {
                           kSpring.constraint.add_cost(model, sink);
                         }
                       }},
};

inline constexpr std::array<const ForceKind*, 12> kForceKinds{
    &kGravity,
    &kFields,
    &kWind,
    &kGlobalDamping,
    &kSpringForces<kAxialSprings, &ForceSwitches::axial_springs, true>,
    &kSpringForces<kBendingSprings, &ForceSwitches::bending>,
    &kSpringForces<kClampSprings, &ForceSwitches::clamps>,
    &kSpringForces<kTorsionSprings, &ForceSwitches::torsion>,
    &kTies,
    &kAxialDampers,
    // The ground after every other kind on the team's nodes: its damper acts on the velocity at
    // t_n that every other force on the node brings about (ground_contact.hpp).
    &kGroundContact,
    // Contact between objects after the team's job: its search shares its loops with the team
    // by itself, then the pairs' forces are added on the calling thread.
    &kObjectContact,
};

// The switches of the kinds the implicit step takes as `treatment`, every other kind off.
inline ForceSwitches switches_treated_as(ImplicitTreatment treatment) {
  ForceSwitches switches = ForceSwitches::none();
  for (const ForceKind* kind : kForceKinds) {
    switches.*kind->switched = kind->implicit == treatment;
  }
  return switches;
}

// The force kind of a spring kind.
inline const ForceKind& force_kind_of(const SpringKind& spring) {
  for (const ForceKind* kind : kForceKinds) {
    if (kind->spring == &spring) {
      return *kind;
    }
  }
  throw std::logic_error(std::string("no force kind holds the ") + spring.name());
}

// The switches with `kind` alone on.
inline ForceSwitches only(const ForceKind& kind) {
  ForceSwitches switches = ForceSwitches::none();
  switches.*kind.switched = true;
  return switches;
}

}  // namespace dinam
