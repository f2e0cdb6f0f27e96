#pragma once
// A kind of force, described once: what the explicit step, the potential and stiffness that
// Newton's method assembles, the implicit step, the energy report and its ledger, the state's
// memory estimate and the run-time estimate need of it (as IPC Toolkit keeps each potential behind
// one generic assembly, and MuJoCo its force kinds in tables). force_kinds.hpp lists every kind in
// the order a step adds their forces; each kind's entry sits in the file of its kernel
// (field_forces.cpp, wind.cpp, ground_contact.cpp, …), the springs' beside their SpringKind
// (spring_kinds.hpp). A hook a kind does not have is null, and every loop skips it.
//
// A new kind of force is its kernel and its entry, one line in kForceKinds and its switch in
// ForceSwitches (beside its tests, its model arrays and its reader).
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/force_switches.hpp"
#include "dynamics/free_dofs.hpp"
#include "dynamics/spring_kind.hpp"
#include "dynamics/state.hpp"
#include "dynamics/stiffness.hpp"
#include "estimate/step_cost_sink.hpp"

namespace dinam {

struct Model;

// What a kind does to the motion's energy.
enum class ForceRole {
  kPotential,    // the gradient of a stored energy: springs, gravity
  kLoad,         // drives from outside, its work booked: the fields, the wind
  kDissipation,  // takes energy out, its work booked: dampers, global viscous friction
  kContact,      // a penalty's stored energy, its damping and friction booked: ground, objects
};

// How the implicit step (solver/implicit_integrator.hpp) takes a kind.
enum class ImplicitTreatment {
  kInPotential,  // a term of the step's potential: its forces and stiffness at every iterate
  kLoadAtEnd,    // a load of the time alone, taken at t_{n+1}
  kLoadAtStart,  // a force that depends on the motion, taken at (x_n, v_n) as a load (lagged)
  kDamper,       // linear in the velocities: its dissipation over the step (ImplicitDamper)
  kOwnContact,   // contact between objects: its penalty and lagged friction
                 // (dynamics/contact/object_contact_implicit.hpp), beside the potential
};

// A part of the energy ledger (state.hpp): the array the kind keeps its own forces in while the
// energy is tracked, and the account their work is booked on.
struct LedgerLine {
  std::vector<Vec3> EnergyWorkspace::*force = nullptr;
  double EnergyAccounts::*work = nullptr;
};

// What a potential is asked for (solver/potential.hpp).
struct PotentialQuery {
  // The positions where gravity's share is zero (n_nodes), so that it holds no large constant.
  const std::vector<Vec3>& gravity_origin;
  SpringEnergy springs;  // the springs' stored energy, or that and their flow's work
};

// A sum of potential energies and the scale of its rounding error.
struct Potential {
  double energy = 0.0;  // J
  // J: the sum of its terms' magnitudes, the scale of its rounding error (about 1e-16 of it):
  // two energies nearer than that cannot tell which configuration is lower.
  double magnitude = 0.0;

  void add(double term) {
    energy += term;
    magnitude += std::abs(term);
  }
};

// A damper under the implicit step (ImplicitTreatment::kDamper): its dissipation over a step of
// h, a quadratic ½ ΔxᵀDΔx of the free nodes' move from the step's base with D taken at x_n (a term
// of the incremental potential, solver/implicit_integrator.hpp).
struct ImplicitDamper {
  // 1/s, a damping in proportion to the masses, D = α M/h on the Hessian's diagonal; null where
  // none.
  double (*mass_rate)(const Model&);
  // D's other terms for a step of h from `x_start` (x_n), as triplets over the free dofs; null
  // where none.
  void (*add_hessian)(const Model&, const State&, const FreeDofs&, const std::vector<Vec3>& x_start,
                      double h, DofTriplets&);
  // N, added to `force` over the free dofs: the pull of its dampers whose other end is a support
  // that moves, from `x_base` to where state.x has placed it at t_{n+1}; null where none.
  void (*add_support_pull)(const Model&, const State&, const FreeDofs&,
                           const std::vector<Vec3>& x_start, const std::vector<Vec3>& x_base,
                           double h, Eigen::VectorXd& force);
};

struct ForceKind {
  const char* label;         // "gravity"; null for a spring kind, whose SpringKind names it
  const SpringKind* spring;  // a spring kind's own half (plastic sets, flow, tearing), else null
  ForceRole role;
  ImplicitTreatment implicit;
  ImplicitDamper damper;          // how the implicit step takes it, for kDamper; nulls otherwise
  bool ForceSwitches::*switched;  // its switch: off, every loop leaves it out (tests isolate kinds)
  // Whether the model holds any of it (null: any model may); a kind absent costs nothing.
  bool (*present)(const Model&);

  // The explicit step (integrator.cpp), on the context worker's own nodes: what it needs before
  // the nodes' totals are cleared (the team meets after it), then its forces added to the
  // total (and, while the energy is tracked, to its ledger lines). A kind whose forces are found
  // after the team's job, on the calling thread, has `add_forces_after_team` instead.
  void (*prepare_forces)(ForceContext& total);
  void (*add_forces)(ForceContext& total, const StepOptions& options);
  void (*add_forces_after_team)(ForceContext& total);

  // Its terms of the potential that Newton's method minimises (solver/potential.hpp), at the
  // state's positions with the histories held; null where it is no potential of the positions.
  void (*add_potential)(const Model&, const State&, const PotentialQuery&, Potential&);
  // Each element's stiffness at the state's positions (stiffness.hpp); null where it has none.
  void (*add_stiffness)(const Model&, const State&, StiffnessSink&);

  // The energy report: the energy it stores, added to its line of the report; null where it
  // stores none. The work it does is booked on its ledger lines (up to two: a contact's damping
  // and its friction).
  void (*report_energy)(const Model&, const State&, EnergyReport&);
  LedgerLine ledger[2];

  // The arrays of the state it needs beyond the nodes' own, allocated by make_state
  // (integrator.hpp), and their bytes, `energy` while the energy is tracked; null where none.
  void (*prepare_state)(const Model&, State&);
  std::uint64_t (*state_bytes)(const Model&, bool energy);
  // Its share of a step's time (estimate/step_cost.hpp): the items it loops over, at their figure
  // in estimate/measured_costs.hpp; null where the nodes' own cost covers it.
  void (*add_cost)(const Model&, StepCostSink&);
  // How `integrator: xpbd` takes it: as forces (nulls), or held as a constraint.
  ConstraintHold constraint;

  const char* name() const { return spring != nullptr ? spring->name() : label; }
  bool acts_in(const Model& model, const ForceSwitches& switches) const {
    return switches.*switched && (present == nullptr || present(model));
  }
  // Whether a run of `model` holds it as a constraint (`integrator: xpbd`).
  bool held_as_constraint(const Model& model) const {
    return constraint.held && model.bars_are_constraints();
  }
};

}  // namespace dinam
