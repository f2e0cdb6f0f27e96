// The one place that maps an integrator kind (scene/scene_description.hpp) to what it does: its
// stepper, its step, its start. Everything above stepping/ asks here.
#include <cmath>

#include "model/model.hpp"
#include "solver/settle.hpp"
#include "stepping/central_difference_stepper.hpp"
#include "stepping/implicit_stepper.hpp"
#include "stepping/time_step.hpp"

namespace dinam {

std::unique_ptr<Stepper> make_stepper(const Model& model, const TimeStep& timestep) {
  if (model.integrator == IntegratorKind::kImplicit) {
    return std::make_unique<ImplicitStepper>(model, timestep);
  }
  return std::make_unique<CentralDifferenceStepper>(model, timestep);
}

bool stepper_copies_model(const Model& model) {
  return model.integrator == IntegratorKind::kImplicit && ImplicitIntegrator::copies_model(model);
}

TimeStep choose_timestep(const Model& model, std::optional<double> requested, double fps,
                         const FileLoc& where) {
  return choose_timestep(model, model.integrator, requested, fps, where);
}

TimeStep choose_timestep(const Model& model, IntegratorKind integrator,
                         std::optional<double> requested, double fps, const FileLoc& where) {
  if (integrator == IntegratorKind::kImplicit) {
    // Stable at any step: `timestep` is the longest it takes (a share of it where the error asks,
    // solver/implicit_integrator.hpp), by default a quarter of a frame.
    TimeStep step = fit_timestep_to_frames(requested.value_or(1.0 / fps / kImplicitStepsPerFrame),
                                           fps, requested, where);
    step.critical = critical_timestep(model);
    step.automatic = !requested.has_value();
    return step;
  }
  return choose_explicit_timestep(model, requested, fps, where);
}

double settling_step(const Model& model, double dt) {
  return model.integrator == IntegratorKind::kImplicit
             ? kAutoTimestepSafety * critical_timestep(model)
             : dt;
}

State initial_state(const Model& model, double dt, const ForceSwitches& switches, bool track_energy,
                    Settling settling) {
  State state = make_state(model, track_energy);
  if (settling == Settling::kRun) {
    settle_under_gravity(model, settling_step(model, dt), switches, state);
  }
  if (model.integrator == IntegratorKind::kCentralDifference) {
    start_leapfrog(model, dt, switches, state);
  }
  return state;
}

}  // namespace dinam
