#include "stepping/integrator_choice.hpp"

#include <optional>

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/stepper_kind.hpp"

namespace dinam {

IntegratorChoice compare_integrators(const SceneDescription& scene, const Model& model, int threads,
                                     bool room_for_another_model) {
  // The motion alone: settling, by Newton's method unless it fails, is the same for both. The
  // other integrator at its automatic step: a `timestep` chosen for one says nothing of the
  // other's.
  const auto run = [&](const Model& built, const StepperKind& kind) {
    const bool own = &kind == &stepper_kind(model);
    const std::optional<double> requested = own ? scene.timestep : std::nullopt;
    const TimeStep step =
        kind.choose_timestep(built, requested, scene.fps, own ? scene.timestep_loc : FileLoc{});
    RunEstimate estimate = estimate_run(scene, built, kind, step, threads);
    estimate.steps -= estimate.settle_steps;
    estimate.settle_steps = 0;
    estimate.seconds = estimate.step.seconds * static_cast<double>(estimate.steps);
    return estimate;
  };
  IntegratorChoice choice;
  choice.contact_envelope = model.contact.enabled;
  if (scene.step_bounded_by_stiffness()) {
    // The implicit integrator's cost is counted from the model's springs and the pattern of its
    // Hessian, which are the same for both (its model differs only in masses central
    // differences scale and the ground's stiffness): the same model serves, and info stays
    // cheap at any size.
    choice.central_difference = run(model, kCentralDifferences);
    choice.implicit = run(model, kImplicitSchemes);
  } else {
    // Central differences' step depends on the masses it scales to lengthen it: their model is
    // built, where the machine has room for a second one; else estimated from this one, without
    // the scaling (so a little long).
    std::optional<Model> other;
    if (room_for_another_model) {
      SceneDescription other_scene = scene;
      other_scene.timestep.reset();
      use_stepper(other_scene, kCentralDifferences);
      other.emplace(build_model(other_scene));
    } else {
      choice.central_difference_unscaled = true;
    }
    choice.central_difference = run(other ? *other : model, kCentralDifferences);
    choice.implicit = run(model, kImplicitSchemes);
  }
  // The implicit integrator where it wins even if its estimate is as far short as the worst
  // measured for structures that move alike (estimate_margin: a free structure's runs took up to
  // ten times theirs, where a wrong choice costs the user that much; the Wuson was once estimated
  // at 19 s and ran over 300 s), by the half that central differences' exact, cheap steps are
  // owed.
  choice.implicit_margin = estimate_margin(choice.implicit.implicit.motion);
  choice.recommended =
      choice.implicit_margin * choice.implicit.seconds < 0.5 * choice.central_difference.seconds
          ? &kImplicitSchemes
          : &kCentralDifferences;
  choice.recommended_scheme = choice.implicit.implicit.motion == ImplicitMotion::kSwings
                                  ? ImplicitScheme::kBdf2
                                  : ImplicitScheme::kBackwardEuler;
  return choice;
}

const char* recommended_key(const IntegratorChoice& choice) {
  if (!choice.recommends_implicit()) {
    return choice.recommended->key;
  }
  return choice.recommended_scheme == ImplicitScheme::kBdf2 ? "implicit_bdf2" : "implicit";
}

const char* recommendation_reason(const IntegratorChoice& choice) {
  if (!choice.recommends_implicit() && choice.implicit_margin > 1.0) {
    return "nothing holds the structure: it lands, folds or tumbles, where the implicit "
           "integrator's runs have taken up to ten times their estimate; even so far short, its "
           "estimate would not be under half of central differences', whose cost is known";
  }
  if (!choice.recommends_implicit()) {
    return "the implicit integrator's estimate is not under half of central differences', which "
           "are exact and cheap per step";
  }
  return choice.recommended_scheme == ImplicitScheme::kBdf2
             ? "its estimate is under half of central differences'; BDF2 since the structure "
               "swings: it keeps a swing that backward Euler would damp away"
             : "its estimate is under half of central differences'; backward Euler, whose "
               "damping settles a structure that lands and folds";
}

}  // namespace dinam
