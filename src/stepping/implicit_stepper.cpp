#include "stepping/implicit_stepper.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <memory>

#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "solver/implicit_damping.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

// Stable at any step: `timestep` is the longest it takes (a share of it where the error asks,
// solver/implicit_integrator.hpp), by default a quarter of a frame.
TimeStep implicit_timestep(const Model& model, std::optional<double> requested, double fps,
                           const FileLoc& where) {
  TimeStep step = fit_timestep_to_frames(requested.value_or(1.0 / fps / kImplicitStepsPerFrame),
                                         fps, requested, where);
  step.critical = critical_timestep(model);
  step.automatic = !requested.has_value();
  return step;
}

// The implicit integrator's numerical damping at the scene's step, for modes resolved by these
// many steps a period (a frequency each, at that step).
constexpr std::array<int, 3> kStepsPerPeriod = {8, 16, 32};

std::vector<ModeDamping> mode_damping(const TimeStep& timestep) {
  std::vector<ModeDamping> modes;
  modes.reserve(kStepsPerPeriod.size());
  for (const int steps : kStepsPerPeriod) {
    modes.push_back({steps, 1.0 / (steps * timestep.dt),
                     amplitude_kept_per_period(ImplicitScheme::kBackwardEuler, steps),
                     amplitude_kept_per_period(ImplicitScheme::kBdf2, steps)});
  }
  return modes;
}

const char* scheme_name(const Model& model) {
  return model.implicit_scheme == ImplicitScheme::kBdf2 ? "BDF2" : "backward Euler";
}

std::string implicit_timestep_note(const Model& model, const TimeStep& timestep) {
  return fmt::format(
      "implicit, {}: stable at any step; {}, halved where a step needs it", scheme_name(model),
      timestep.automatic ? fmt::format("auto: 1/{} of a frame", kImplicitStepsPerFrame)
                         : "from the scene");
}

std::string implicit_energy_balance_note(const Model& model, const TimeStep& timestep) {
  const bool bdf2 = model.implicit_scheme == ImplicitScheme::kBdf2;
  std::vector<std::string> kept;
  std::vector<std::string> other;
  for (const ModeDamping& mode : mode_damping(timestep)) {
    kept.push_back(fmt::format("{:.3g} Hz ({} steps) {:.0f} %", mode.frequency,
                               mode.steps_per_period,
                               100.0 * (bdf2 ? mode.bdf2 : mode.backward_euler)));
    other.push_back(fmt::format("{:.0f} %", 100.0 * (bdf2 ? mode.backward_euler : mode.bdf2)));
  }
  return fmt::format(
      "the implicit integrator books what its scheme takes out as energy.csv's "
      "numerical_dissipation_J, and total_J holds to what Newton's method leaves out of "
      "balance; at steps of {:.3g} s {} keeps of a mode's amplitude a period: {} ('{}': {})",
      timestep.dt, scheme_name(model), fmt::join(kept, ", "),
      bdf2 ? "integrator: implicit" : "integrator: implicit_bdf2", fmt::join(other, ", "));
}

}  // namespace

State ImplicitStepper::start(bool track_energy, Settling settling) {
  State state = initial_state(integrator_.model(), timestep_.dt, {}, track_energy, settling);
  integrator_.report_energy(state);
  return state;
}

void ImplicitStepper::advance(State& state, std::int64_t steps) {
  integrator_.advance(state, timestep_.dt, steps);
}

void ImplicitStepper::velocity_now(State& state, std::vector<Vec3>& v) const {
  v = state.velocity;
}

const StepperKind kImplicitSchemes = {
    .key = "implicit",
    .choose_timestep = implicit_timestep,
    .settling_step = [](const Model& model,
                        double) { return kAutoTimestepSafety * critical_timestep(model); },
    .finish_start = nullptr,
    .make_stepper = [](const Model& model, const TimeStep& timestep) -> std::unique_ptr<Stepper> {
      return std::make_unique<ImplicitStepper>(model, timestep);
    },
    .copies_model = ImplicitIntegrator::copies_model,
    .timestep_note = implicit_timestep_note,
    .energy_balance_note = implicit_energy_balance_note,
    .numerical_damping = mode_damping,
};

}  // namespace dinam
