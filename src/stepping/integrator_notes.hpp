#pragma once
// What `dinam info` says of an integrator: its key, its step, its run time and how its energy
// balance holds, each in the words of the integrator it describes, so that info itself never
// branches on the integrator.
#include <string>
#include <vector>

#include "dynamics/stability.hpp"
#include "scene/scene_description.hpp"
#include "stepping/run_estimate.hpp"

namespace dinam {

struct Model;

// The share of a mode's amplitude each implicit scheme keeps over a period, for a mode resolved
// by `steps_per_period` steps of the run (of `frequency` at that step).
struct ModeDamping {
  int steps_per_period = 0;
  double frequency = 0.0;       // Hz
  double backward_euler = 0.0;  // share of the amplitude kept over a period
  double bdf2 = 0.0;
};

// How well central differences' energy report balances at the run's step (see the .cpp).
struct EnergyBalanceGuide {
  double omega_dt = 0.0;      // ω_max Δt, ω_max the stability bound's
  double balance = 0.0;       // expected worst |total − start| / peak kinetic energy
  double step_for_0_1 = 0.0;  // s, the step that brings it to 0.1 %
};
EnergyBalanceGuide energy_balance_guide(const Model& model, const TimeStep& timestep);

// The scene's `integrator` value: "central_difference", "implicit" (either implicit scheme).
const char* integrator_key(IntegratorKind kind);

// How the step was chosen, for "time step 0.0125 s (…)".
std::string timestep_note(const Model& model, const TimeStep& timestep);

// The "run time" line's text after its label: the estimate and what it is made of.
std::string run_time_note(const Model& model, const RunEstimate& estimate);

// Whether a step can be timed now on this machine (measure_step_now times central differences'
// step; an implicit step is a Newton solve, which it does not measure).
bool step_can_be_timed(const Model& model);

// The "energy balance" line's text after its label: what the energy report's balance holds to.
std::string energy_balance_note(const Model& model, const TimeStep& timestep);

// The amplitude each scheme keeps of a mode a period at the run's step, for the implicit
// schemes' numerical damping (solver/implicit_damping.hpp); empty for central differences, which
// have none.
std::vector<ModeDamping> numerical_damping(const Model& model, const TimeStep& timestep);

}  // namespace dinam
