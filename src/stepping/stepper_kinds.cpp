// The one place that maps the scene's `integrator` (scene/scene_description.hpp) to its kind
// (stepper_kind.hpp); everything else asks the kind.
#include "model/model.hpp"
#include "solver/settle.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

namespace dinam {

const StepperKind& stepper_kind(const Model& model) {
  switch (model.integrator) {
    case IntegratorKind::kImplicit:
      return kImplicitSchemes;
    case IntegratorKind::kXpbd:
      return kBarConstraints;
    case IntegratorKind::kCentralDifference:
      break;
  }
  return kCentralDifferences;
}

void use_stepper(SceneDescription& scene, const StepperKind& kind) {
  scene.integrator = &kind == &kImplicitSchemes  ? IntegratorKind::kImplicit
                     : &kind == &kBarConstraints ? IntegratorKind::kXpbd
                                                 : IntegratorKind::kCentralDifference;
}

TimeStep choose_timestep(const Model& model, std::optional<double> requested, double fps,
                         const FileLoc& where) {
  return stepper_kind(model).choose_timestep(model, requested, fps, where);
}

double settling_step(const Model& model, double dt) {
  return stepper_kind(model).settling_step(model, dt);
}

State initial_state(const Model& model, double dt, const ForceSwitches& switches, bool track_energy,
                    Settling settling) {
  State state = make_state(model, track_energy);
  const StepperKind& kind = stepper_kind(model);
  if (settling == Settling::kRun) {
    settle_under_gravity(model, kind.settling_step(model, dt), switches, state);
  }
  if (kind.finish_start != nullptr) {
    kind.finish_start(model, dt, switches, state);
  }
  return state;
}

}  // namespace dinam
