#include "estimate/integrator_choice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/stepper_kind.hpp"

namespace dinam {
namespace {

// The share of a frame within which the bars' stretch waves must cross every object for the bars
// to be held as constraints: their stretching is then over long before a frame shows it.
constexpr double kStretchCrossingShare = 0.25;

// Why holding the bars as constraints would change what a user sees of `model`, or empty: a
// structure free to land (`free_to_land`: nothing holds it, estimate/implicit_cost.hpp); contact
// within an object, which fights the projection (model_builder refuses it); a structure whose bars
// stretch visibly moves by its stretch (a rubber net the ball dips into: its stretch waves cross
// it in 15 ms at c = √(E/ρ) = 130 m/s, where cotton's do in 5 ms at 290 m/s): each bar's wave
// speed is its length times √(k (1/m_i + 1/m_j) / 2), √(E/ρ) on a uniform wire, and an object's
// slowest crosses its size.
std::string xpbd_unfit(const Model& model, double fps, bool free_to_land) {
  if (free_to_land) {
    // Its landings are what one sees, and the ground's penalty, made for the constraints' longer
    // step, is softer: the shipped ball and wire chair ended 27 and 42 cm from where central
    // differences put them, which a step of 0.7 of theirs moves by 3 and 2 cm.
    return "nothing holds the structure, and its landings on a ground made softer for the longer "
           "step go otherwise";
  }
  for (const std::uint8_t self : model.contact.object_self) {
    if (self != 0) {
      return "contact within an object fights the bars' projection";
    }
  }
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ModelObject& object = model.objects[k];
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (Index i = object.first_node; i < object.first_node + object.node_count; ++i) {
      low = low.cwiseMin(model.node_initial_x[i]);
      high = high.cwiseMax(model.node_initial_x[i]);
    }
    double slowest = std::numeric_limits<double>::infinity();  // m/s
    for (Index b = object.first_bar; b < object.first_bar + object.bar_count; ++b) {
      const double inverse_masses = model.node_inv_mass[model.bar_nodes[2 * b]] +
                                    model.node_inv_mass[model.bar_nodes[2 * b + 1]];
      if (model.bar_axial_stiffness[b] > 0.0 && inverse_masses > 0.0) {
        slowest =
            std::min(slowest, model.bar_rest_length[b] *
                                  std::sqrt(0.5 * model.bar_axial_stiffness[b] * inverse_masses));
      }
    }
    if (object.node_count > 0 && (high - low).norm() / slowest > kStretchCrossingShare / fps) {
      return fmt::format(
          "object '{}' stretches visibly: its bars' stretch waves take {:.3g} ms to "
          "cross it, over a quarter frame",
          object.name, 1e3 * (high - low).norm() / slowest);
    }
  }
  return {};
}

}  // namespace

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
  if (scene.integrator == IntegratorKind::kCentralDifference) {
    // The implicit integrator's cost is counted from the model's springs and the pattern of its
    // Hessian, which are the same for both (its model differs only in masses central
    // differences scale and the ground's stiffness): the same model serves, and info stays
    // cheap at any size.
    choice.central_difference = run(model, kCentralDifferences);
    choice.implicit = run(model, kImplicitSchemes);
    choice.xpbd = run(model, kBarConstraints);  // its step and cost leave the bars out
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
    choice.xpbd = run(other ? *other : model, kBarConstraints);
  }
  // The implicit integrator where it wins even if its estimate is as far short as the worst
  // measured for structures that move alike (estimate_margin: a free structure's runs took up to
  // ten times theirs, where a wrong choice costs the user that much; the Wuson was once estimated
  // at 19 s and ran over 300 s), by the half that central differences' exact, cheap steps are
  // owed.
  choice.implicit_margin = estimate_margin(choice.implicit.implicit.motion);
  // The bars as constraints where their explicit steps, counted as central differences' are,
  // come under half of central differences' time; then the implicit integrator only where it
  // beats that by the same half.
  double best = choice.central_difference.seconds;
  choice.xpbd_unfit = xpbd_unfit(model, scene.fps, choice.implicit_margin > 1.0);
  if (choice.xpbd_unfit.empty() && choice.xpbd.seconds < 0.5 * best) {
    choice.recommended = &kBarConstraints;
    best = choice.xpbd.seconds;
  }
  if (choice.implicit_margin * choice.implicit.seconds < 0.5 * best) {
    choice.recommended = &kImplicitSchemes;
  }
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

namespace {

const char* reason_for(const IntegratorChoice& choice) {
  if (choice.recommends_xpbd()) {
    return "the bars' stretch sets central differences' step; held as constraints, the other "
           "springs set it, and the estimate is under half of central differences'";
  }
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

}  // namespace

std::string recommendation_reason(const IntegratorChoice& choice) {
  std::string reason = reason_for(choice);
  if (!choice.recommends_xpbd() && !choice.xpbd_unfit.empty() &&
      choice.xpbd.seconds < 0.5 * choice.central_difference.seconds) {
    reason += "; 'xpbd' would be faster, but " + choice.xpbd_unfit;
  }
  return reason;
}

}  // namespace dinam
