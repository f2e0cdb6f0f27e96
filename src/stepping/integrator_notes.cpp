#include "stepping/integrator_notes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "solver/implicit_damping.hpp"

namespace dinam {
namespace {

// Central differences keep a shadow of the energy, not the energy itself: in a mode of frequency ω
// the measured energy swings by a share that grows as (ω Δt)². How much of it shows in the
// balance depends on how much motion reaches the stiffest modes, so the figure is scaled from a
// measured scene: the paper's flag undamped (a 20 × 12 cloth, E = 2e7 Pa, r = 1 mm, pushed
// sideways, 100 000 steps at its automatic step, ω_max Δt = 1.6) keeps its balance within 2.3 % of
// its peak kinetic energy, 0.6 % at half the step and 0.13 % at a quarter (docs/scene-format.md,
// "Output").
constexpr double kReferenceOmegaDt = 1.6;
constexpr double kReferenceBalance = 0.023;

// The implicit integrator's numerical damping at the scene's step, for modes resolved by these
// many steps a period (a frequency each, at that step).
constexpr std::array<int, 3> kStepsPerPeriod = {8, 16, 32};

std::vector<ModeDamping> implicit_mode_damping(const TimeStep& timestep) {
  std::vector<ModeDamping> modes;
  modes.reserve(kStepsPerPeriod.size());
  for (const int steps : kStepsPerPeriod) {
    modes.push_back({steps, 1.0 / (steps * timestep.dt),
                     amplitude_kept_per_period(ImplicitScheme::kBackwardEuler, steps),
                     amplitude_kept_per_period(ImplicitScheme::kBdf2, steps)});
  }
  return modes;
}

}  // namespace

EnergyBalanceGuide energy_balance_guide(const Model& model, const TimeStep& timestep) {
  EnergyBalanceGuide guide;
  guide.omega_dt = std::sqrt(max_frequency_squared_bound(model)) * timestep.dt;
  const double ratio = guide.omega_dt / kReferenceOmegaDt;
  guide.balance = kReferenceBalance * ratio * ratio;
  guide.step_for_0_1 = timestep.dt * std::min(1.0, std::sqrt(0.001 / guide.balance));
  return guide;
}

const char* integrator_key(IntegratorKind kind) {
  return kind == IntegratorKind::kImplicit ? "implicit" : "central_difference";
}

std::string timestep_note(const Model& model, const TimeStep& timestep) {
  if (model.integrator == IntegratorKind::kImplicit) {
    return fmt::format(
        "implicit, backward Euler: stable at any step; {}, halved where a step "
        "needs it",
        timestep.automatic ? fmt::format("auto: 1/{} of a frame", kImplicitStepsPerFrame)
                           : "from the scene");
  }
  return timestep.automatic ? fmt::format("auto: at most {} × the limit", kAutoTimestepSafety)
                            : "from the scene, fitted to whole steps per frame";
}

std::string run_time_note(const Model& model, const RunEstimate& estimate) {
  const StepCost& cost = estimate.step;
  if (model.integrator == IntegratorKind::kImplicit) {
    return fmt::format(
        "about {} to simulate ({:.3g} ms a step, a Newton solve, estimated from the model's "
        "springs and the size of its Hessian's factor; drawing comes on top)",
        duration_text(estimate.seconds), 1e3 * cost.seconds);
  }
  return fmt::format(
      "about {} to simulate ({:.3g} ms a step on {} thread{}, estimated from the model's springs "
      "and nodes; drawing comes on top){}",
      duration_text(estimate.seconds), 1e3 * cost.seconds, cost.threads,
      cost.threads == 1 ? "" : "s",
      estimate.long_run() ? fmt::format("; over {}, so render and simulate refuse it without "
                                        "--force",
                                        duration_text(kLongRunSeconds))
                          : "");
}

bool step_can_be_timed(const Model& model) {
  return model.integrator == IntegratorKind::kCentralDifference;
}

std::string energy_balance_note(const Model& model, const TimeStep& timestep) {
  if (model.integrator == IntegratorKind::kImplicit) {
    const bool bdf2 = model.implicit_scheme == ImplicitScheme::kBdf2;
    std::vector<std::string> kept;
    std::vector<std::string> other;
    for (const ModeDamping& mode : implicit_mode_damping(timestep)) {
      kept.push_back(fmt::format("{:.3g} Hz ({} steps) {:.0f} %", mode.frequency,
                                 mode.steps_per_period,
                                 100.0 * (bdf2 ? mode.bdf2 : mode.backward_euler)));
      other.push_back(fmt::format("{:.0f} %", 100.0 * (bdf2 ? mode.backward_euler : mode.bdf2)));
    }
    return fmt::format(
        "the implicit integrator books what its scheme takes out as energy.csv's "
        "numerical_dissipation_J, and total_J holds to what Newton's method leaves out of "
        "balance; at steps of {:.3g} s {} keeps of a mode's amplitude a period: {} ('{}': {})",
        timestep.dt, bdf2 ? "BDF2" : "backward Euler", fmt::join(kept, ", "),
        bdf2 ? "integrator: implicit" : "integrator: implicit_bdf2", fmt::join(other, ", "));
  }
  const EnergyBalanceGuide guide = energy_balance_guide(model, timestep);
  return fmt::format(
      "ω_max·Δt = {:.2f}; central differences' energy error grows as (ω·Δt)²: "
      "where the motion shakes the stiffest bars, energy.csv's total_J may stray by up to about "
      "{:.2g} % of the peak kinetic energy (scaled from an undamped cloth flag's 2.3 % at 1.6), "
      "far less in gentle motion; 'timestep: {:.3g}' brings that to about 0.1 %",
      guide.omega_dt, 100.0 * guide.balance, guide.step_for_0_1);
}

std::vector<ModeDamping> numerical_damping(const Model& model, const TimeStep& timestep) {
  if (model.integrator != IntegratorKind::kImplicit) {
    return {};
  }
  return implicit_mode_damping(timestep);
}

}  // namespace dinam
