#include "app/integrator_choice.hpp"

#include <optional>

#include "core/error.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"

namespace dinam {

IntegratorChoice compare_integrators(const SceneDescription& scene, const Model& model,
                                     int threads) {
  const auto run = [&](const SceneDescription& run_scene, const Model& built) {
    const TimeStep step =
        choose_timestep(built, run_scene.timestep, run_scene.fps, run_scene.timestep_loc);
    // The motion alone: settling, by Newton's method unless it fails, is the same for both.
    RunEstimate estimate = estimate_run(run_scene, built, step, threads);
    estimate.steps -= estimate.settle_steps;
    estimate.settle_steps = 0;
    estimate.seconds = estimate.step.seconds * static_cast<double>(estimate.steps);
    return estimate;
  };
  // The other integrator at its automatic step: a `timestep` chosen for one says nothing of the
  // other's.
  const bool implicit = model.integrator == IntegratorKind::kImplicit;
  SceneDescription other_scene = scene;
  other_scene.timestep.reset();
  other_scene.integrator =
      implicit ? IntegratorKind::kCentralDifference : IntegratorKind::kImplicit;
  IntegratorChoice choice;
  std::optional<Model> other;
  try {
    other.emplace(build_model(other_scene));
  } catch (const UserError& e) {
    // What the implicit integrator does not handle yet (model_builder.cpp says which).
    choice.implicit_refused = e.message();
    choice.central_difference = run(scene, model);
    return choice;
  }
  choice.central_difference = implicit ? run(other_scene, *other) : run(scene, model);
  choice.implicit = implicit ? run(scene, model) : run(other_scene, *other);
  choice.contact_envelope = model.contact.enabled;
  choice.recommended = choice.implicit.seconds < 0.5 * choice.central_difference.seconds
                           ? IntegratorKind::kImplicit
                           : IntegratorKind::kCentralDifference;
  return choice;
}

}  // namespace dinam
