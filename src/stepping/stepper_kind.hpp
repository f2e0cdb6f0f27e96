#pragma once
// An integrator, described once (as dynamics/force_kind.hpp describes a kind of force): what a
// run and `dinam info` need of it — its stepper, the step it takes, where it starts and the notes
// `info` prints (its estimates: estimate/integrator_estimates.hpp). Each kind's entry sits in its
// stepper's file (central_difference_stepper.cpp, implicit_stepper.cpp); stepper_kinds.cpp alone
// maps the scene's `integrator` to its entry, so that nothing else branches on the integrator.
//
// A new integrator is its stepper, its entry, one case in stepper_kinds.cpp and its estimates
// (estimate/integrator_estimates.cpp), beside its reader and its tests.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dynamics/force_switches.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/state.hpp"
#include "stepping/stepper.hpp"

namespace dinam {

struct Model;
struct SceneDescription;

// The share of a mode's amplitude each implicit scheme keeps over a period, for a mode resolved
// by `steps_per_period` steps of the run (of `frequency` at that step).
struct ModeDamping {
  int steps_per_period = 0;
  double frequency = 0.0;       // Hz
  double backward_euler = 0.0;  // share of the amplitude kept over a period
  double bdf2 = 0.0;
};

struct StepperKind {
  const char* key;  // the scene's `integrator` value: "central_difference", "implicit"

  // The run's step: `requested` (the scene's `timestep`; empty: automatic), fitted to whole steps
  // a frame, refused naming `where` where the kind cannot take it.
  TimeStep (*choose_timestep)(const Model&, std::optional<double> requested, double fps,
                              const FileLoc& where);
  // The step the settling phase relaxes by (solver/settle.hpp) in a run of steps of `dt`.
  double (*settling_step)(const Model&, double dt);
  // What the kind does to the settled state at t = 0 before its first step (leapfrog's half step
  // back); null where nothing.
  void (*finish_start)(const Model&, double dt, const ForceSwitches&, State&);
  std::unique_ptr<Stepper> (*make_stepper)(const Model&, const TimeStep&);
  // Whether its stepper holds a copy of the model, which a memory estimate counts.
  bool (*copies_model)(const Model&);

  // What `dinam info` says, each after its line's label: how the step was chosen ("time step");
  // what the energy report's balance holds to ("energy balance"). What the estimates need of an
  // integrator is in estimate/integrator_estimates.hpp.
  std::string (*timestep_note)(const Model&, const TimeStep&);
  std::string (*energy_balance_note)(const Model&, const TimeStep&);
  // The amplitude each implicit scheme keeps of a mode a period at the run's step; null where the
  // kind damps no mode numerically.
  std::vector<ModeDamping> (*numerical_damping)(const TimeStep&);
};

// Central differences (the paper's method), the same with the bars held as constraints (XPBD: the
// solver for stiff threads) and the implicit schemes (backward Euler, BDF2).
extern const StepperKind kCentralDifferences;
extern const StepperKind kBarConstraints;
extern const StepperKind kImplicitSchemes;

// The kind of the model's integrator (model.integrator).
const StepperKind& stepper_kind(const Model& model);

// `scene` with `kind` as its integrator (`dinam info` builds central differences' model for an
// implicit scene).
void use_stepper(SceneDescription& scene, const StepperKind& kind);

}  // namespace dinam
