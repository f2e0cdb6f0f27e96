#include "stepping/central_difference_stepper.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "dynamics/bar_constraints.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/spring_kind.hpp"
#include "dynamics/stability.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

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

std::string leapfrog_timestep_note(const Model&, const TimeStep& timestep) {
  return timestep.automatic ? fmt::format("auto: at most {} × the limit", kAutoTimestepSafety)
                            : "from the scene, fitted to whole steps per frame";
}

std::string leapfrog_energy_balance_note(const Model& model, const TimeStep& timestep) {
  const EnergyBalanceGuide guide = energy_balance_guide(model, timestep);
  return fmt::format(
      "ω_max·Δt = {:.2f}; central differences' energy error grows as (ω·Δt)²: "
      "where the motion shakes the stiffest bars, energy.csv's total_J may stray by up to about "
      "{:.2g} % of the peak kinetic energy (scaled from an undamped cloth flag's 2.3 % at 1.6), "
      "far less in gentle motion; 'timestep: {:.3g}' brings that to about 0.1 %",
      guide.omega_dt, 100.0 * guide.balance, guide.step_for_0_1);
}

}  // namespace

State CentralDifferenceStepper::start(bool track_energy, Settling settling) {
  return initial_state(model_, timestep_.dt, {}, track_energy, settling);
}

void CentralDifferenceStepper::advance(State& state, std::int64_t steps) {
  advance_steps(model_, timestep_.dt, {}, state, steps);
}

void CentralDifferenceStepper::velocity_now(State& state, std::vector<Vec3>& v) const {
  compute_forces(model_, stepped_switches(model_, {}), state, false);
  v.resize(state.velocity.size());
  const double half = 0.5 * timestep_.dt;
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = state.velocity[i] + (half * model_.node_inv_mass[i]) * state.force[i];
  }
}

EnergyBalanceGuide energy_balance_guide(const Model& model, const TimeStep& timestep) {
  EnergyBalanceGuide guide;
  guide.omega_dt = std::sqrt(max_frequency_squared_bound(model)) * timestep.dt;
  const double ratio = guide.omega_dt / kReferenceOmegaDt;
  guide.balance = kReferenceBalance * ratio * ratio;
  guide.step_for_0_1 = timestep.dt * std::min(1.0, std::sqrt(0.001 / guide.balance));
  return guide;
}

const StepperKind kCentralDifferences = {
    .key = "central_difference",
    .choose_timestep =
        [](const Model& model, std::optional<double> requested, double fps, const FileLoc& where) {
          return choose_explicit_timestep(model, requested, fps, where);
        },
    .settling_step = [](const Model&, double dt) { return dt; },
    .finish_start = start_leapfrog,
    .make_stepper = [](const Model& model, const TimeStep& timestep) -> std::unique_ptr<Stepper> {
      return std::make_unique<CentralDifferenceStepper>(model, timestep);
    },
    .copies_model = [](const Model&) { return false; },
    .timestep_note = leapfrog_timestep_note,
    .energy_balance_note = leapfrog_energy_balance_note,
    .numerical_damping = nullptr,
};

namespace {

// The bound without the bars. Asked of another integrator's model (`dinam info`, whose estimate
// does not build a model of its own), whose contact penalties were made for that integrator's
// bound: an xpbd model's are made for its own, so the contact keeps its share of the bound.
TimeStep constrained_timestep(const Model& model, std::optional<double> requested, double fps,
                              const FileLoc& where) {
  if (requested) {
    return choose_explicit_timestep(model, requested, fps, where, BarsIn::kConstraints);
  }
  if (model.bars_are_constraints()) {
    TimeStep step = choose_explicit_timestep(model, requested, fps, where, BarsIn::kConstraints);
    const double cap = bar_constraint_step_cap(model);
    if (step.dt > cap) {
      const double critical = step.critical;
      step = fit_timestep_to_frames(cap, fps, requested, where);
      step.critical = critical;
      step.automatic = true;
    }
    return step;
  }
  const double structure = max_frequency_squared_bound(model, false);
  const double held = max_frequency_squared_bound(model, false, BarsIn::kConstraints);
  const double contact_share =
      structure > 0.0 ? max_frequency_squared_bound(model, true) / structure : 1.0;
  // The ground's damper, 2 ζ ω_c a node, for the penalty an xpbd model would give it.
  double ground_rate = 0.0;
  if (model.ground.enabled && model.ground.automatic_frequency_squared && structure > 0.0) {
    ground_rate = 2.0 * model.ground.damping_ratio *
                  std::sqrt(*model.ground.automatic_frequency_squared * held / structure);
  }
  const double critical = critical_timestep_of(
      contact_share * held,
      max_damping_rate_bound(model, BarsIn::kConstraints, false) + ground_rate);
  TimeStep step = fit_timestep_to_frames(
      std::min(kAutoTimestepSafety * critical, bar_constraint_step_cap(model)), fps, requested,
      where);
  step.critical = critical;
  step.automatic = true;
  return step;
}

std::string constrained_timestep_note(const Model& model, const TimeStep& timestep) {
  if (timestep.automatic &&
      bar_constraint_step_cap(model) < kAutoTimestepSafety * timestep.critical) {
    return fmt::format(
        "auto: the bars are constraints, so the other springs' limit, {:.3g} s, is the "
        "stability's; shortened to {:.3g} s, within which gravity and the fields move a node by "
        "{:g} of the median bar, as the projection's few sweeps need",
        timestep.critical, bar_constraint_step_cap(model), kLoadStretchShare);
  }
  return leapfrog_timestep_note(model, timestep) +
         "; the bars are constraints, so the limit is the other springs'";
}

// What the projection takes out of a swing, measured: a 1 m hemp rope of 40 bars let swing from
// 10° (steps of 1.1 ms) loses 1.2 % of its amplitude a period where central differences lose none
// (tests/acceptance/stiff_threads.py checks it, bench/notes/stiff-threads.md).
constexpr double kRopeSwingLossPerPeriod = 0.012;
constexpr double kRopeSwingStep = 1.1e-3;

std::string constrained_energy_balance_note(const Model&, const TimeStep& timestep) {
  return fmt::format(
      "the bars are held as constraints by {} sweeps of XPBD a step; the work their projection "
      "does is booked as energy.csv's numerical_dissipation_J (the bars store none), so total_J "
      "holds as central differences' does; it takes out about {:.1f} % of a hanging rope's swing "
      "a period at steps of {:.2g} s (this scene's: {:.3g} s), where central differences take "
      "out none",
      kConstraintSweeps, 100.0 * kRopeSwingLossPerPeriod, kRopeSwingStep, timestep.dt);
}

}  // namespace

const StepperKind kBarConstraints = {
    .key = "xpbd",
    .choose_timestep = constrained_timestep,
    // Relaxation steps the bars as springs (StepOptions::bars_as_springs), which bound its step.
    .settling_step =
        [](const Model& model, double) {
          return kAutoTimestepSafety * critical_timestep(model, BarsIn::kSprings);
        },
    .finish_start = start_leapfrog,
    .make_stepper = [](const Model& model, const TimeStep& timestep) -> std::unique_ptr<Stepper> {
      return std::make_unique<CentralDifferenceStepper>(model, timestep);
    },
    .copies_model = [](const Model&) { return false; },
    .timestep_note = constrained_timestep_note,
    .energy_balance_note = constrained_energy_balance_note,
    .numerical_damping = nullptr,
};

}  // namespace dinam
