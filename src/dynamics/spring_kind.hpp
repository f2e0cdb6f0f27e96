#pragma once
// A kind of spring, described once (the idea of IPC Toolkit's potentials behind one generic
// assembly, and of MuJoCo's tables): what the step, the energy report, tearing, the state's
// allocation, the memory estimate and the run-time estimate need of it. Each kind's entry sits in
// its own file beside its kernel (axial_spring.cpp, …); spring_kinds.hpp lists them in the order a
// step adds their forces. A new kind of spring is its kernel and entry here, its builder and the
// model stage's entry (model/model_spring_kind.hpp) beside it, its arrays in model.hpp and
// state.hpp (and their lists), its reader and doc row, and one line in each stage's list.
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/state.hpp"
#include "dynamics/stiffness.hpp"
#include "estimate/step_cost_sink.hpp"
#include "model/model.hpp"
#include "model/model_spring_kinds.hpp"

namespace dinam {

// What a kind's energy counts (SpringKind::energy): the elastic energy stored; or that and the work
// that the flow from the state's plastic sets to the present positions would dissipate, whose
// gradient is the flattened force: the springs' share of the incremental potential that an
// implicit step minimises with its plastic sets held at the step's start (a return mapping at
// every iterate).
enum class SpringEnergy { kStored, kWithFlow };

// How the solver for stiff threads (`integrator: xpbd`) takes a kind of force: held as a
// constraint, its forces are left out of the explicit half of each step (stepped_switches,
// integrator.hpp), and its projection runs after that half, kConstraintSweeps Gauss–Seidel sweeps
// a step (XPBD: bar_constraints.hpp), which the velocities then follow.
struct ConstraintHold {
  bool held = false;  // whether `integrator: xpbd` holds the kind as a constraint
  // Sweep number `sweep` (from 0: the step's first, which starts its multipliers afresh) of its
  // projection of state.x_next (x̃_{n+1} in, x_{n+1} out) from state.x (x_n), for a step of h, on
  // one thread; null where another kind's projection takes it in (the bars' dampers, the bars').
  void (*project)(const Model&, double h, int sweep, State&);
  // After the step's last sweep: what flowed plastically moved into the plastic sets (and its
  // work into the ledger's flow, while the energy is tracked); null where nothing can.
  void (*finish)(const Model&, double h, State&);
  // Its projection's share of a step's time (estimate/step_cost.hpp): all its sweeps, on one
  // thread.
  void (*add_cost)(const Model&, StepCostSink&);
};

// Sweeps of the projection a step: each costs a tenth of a step's forces on a cloth, and the
// bars' stretch left after them is a share of what one step's loads would stretch them by. Four
// keep the windy flag's mean within 1.1 cm of central differences' over frames 20–120 (2: 1.3,
// 3: 1.8, 6: 1.0; bench/notes/stiff-threads.md).
inline constexpr int kConstraintSweeps = 4;

struct SpringKind {
  // The model stage's half (model/model_spring_kind.hpp): its name, arrays, stability bound and
  // tearing.
  const ModelSpringKind* built;
  void (*add_forces)(ForceContext&);                           // on the context worker's own nodes
  double (*energy)(const Model&, const State&, SpringEnergy);  // J, of the springs not broken
  // Each spring's stiffness matrix at the state's positions (stiffness.hpp), for Newton's method:
  // the Jacobian of its forces, plastic sets held, of the springs not broken.
  void (*add_stiffness)(const Model&, const State&, StiffnessSink&);
  double EnergyReport::*report;                // the report's line it is booked on
  std::vector<double> State::*plastic_set;     // (count, or empty when none yields)
  std::vector<double> EnergyWorkspace::*flow;  // J its flow dissipated in the last step
  std::vector<std::uint8_t> State::*broken;    // tearing: 1 for a broken one (empty: cannot)
  // Nanoseconds per spring on one thread, elastic and of a kind that can yield: its figures in
  // estimate/measured_costs.hpp, which only the run-time estimate reads.
  double ns_per_item;
  double ns_per_item_yielding;
  ConstraintHold constraint;  // for `integrator: xpbd`

  const char* name() const { return built->name; }  // "bending springs"
  Index count(const Model& model) const { return built->count(model); }
  // Whether some can flow plastically; if none, the state keeps no plastic sets or flows for the
  // kind (model.hpp).
  bool yields(const Model& model) const { return model.*built->yields; }
};

}  // namespace dinam
