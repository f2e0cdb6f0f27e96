#include "model/step_aiming.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "model/frequency_bound.hpp"
#include "model/mass_scaling.hpp"

namespace dinam {
namespace {

// The least `weld` fractions a `timestep: {target}` tries in turn, from each object's own, while
// mass scaling alone would add more than its limit.
constexpr std::array<double, 5> kWeldFloors = {0.0, 0.05, 0.1, 0.2, 0.3};

// The springs alone may vibrate at most this ω² for the finished model's limit, with the ground's
// and the contacts' penalties (each ¼ of the springs' bound, contact on two sides) and every
// damper, to allow `step` / kAutoTimestepSafety: ω²Δt²/4 + γΔt/2 ≤ 1 is the damped
// central-difference limit, the ground's damping rate at most 2ζ_g ω_g ≤ ζ_g ω.
double springs_frequency_for_step(const SceneDescription& scene, const Model& model, double step) {
  const double limit = step / kAutoTimestepSafety;
  const double allowance = 1.0 + (scene.ground.contact ? 0.25 : 0.0) +
                           (scene.contact.objects || scene.contact.self ? 0.5 : 0.0);
  const double ground_zeta = scene.ground.contact ? scene.ground.damping_ratio : 0.0;
  const double gamma = max_damping_rate_bound(model);
  // allowance ω² + (2ζ_g/Δt) ω − (4/Δt²)(1 − γΔt/2) ≤ 0, at its positive root.
  const double a = allowance;
  const double b = 2.0 * ground_zeta / limit;
  const double c = -4.0 / (limit * limit) * std::max(0.0, 1.0 - 0.5 * gamma * limit);
  const double omega = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return omega * omega;
}

// The step `timestep: {target}` or `{max_steps}` asks for: with max_steps, the longest step that
// fills every frame with whole steps and takes at most that many over the frames.
double aimed_step(const SceneDescription& scene) {
  const StepTargetDesc& aim = scene.step_target;
  if (aim.target) {
    return *aim.target;
  }
  const double frames = scene.frame_count();
  const double per_frame = std::floor(*aim.max_steps / frames);
  if (per_frame < 1.0) {
    throw_user_error(aim.loc,
                     "'timestep.max_steps' {:g} is fewer than the {:g} frames, and every frame "
                     "needs at least one step; allow at least {:g}",
                     *aim.max_steps, frames, frames);
  }
  return 1.0 / (scene.fps * per_frame);
}

}  // namespace

void scale_masses(const SceneDescription& scene, const ShortBarPlan& plan, Model& model) {
  // A step given as a number is the user's choice: nothing to lengthen it for. The implicit
  // integrator's step is not bounded by the stiffest bars: nothing to add mass for.
  if (!scene.step_target.mass_scaling || (scene.timestep && !plan.target_step) ||
      !scene.step_bounded_by_stiffness()) {
    return;
  }
  const NodeFrequencyRows rows = node_frequency_rows(model, false);
  if (plan.target_step) {
    model.mass_scaling =
        scale_masses_to(model, rows, springs_frequency_for_step(scene, model, *plan.target_step));
    model.mass_scaling.target_step = *plan.target_step;
    return;
  }
  const std::optional<DefaultScaling> chosen =
      default_scaling_frequency(model, rows, scene.step_target.max_added_mass);
  if (chosen) {
    model.mass_scaling = scale_masses_to(model, rows, chosen->omega_squared);
    model.mass_scaling.capped = chosen->capped;
  }
}

Model build_aiming_at_step(const SceneDescription& scene, const BuildWithPlan& build_once) {
  const StepTargetDesc& aim = scene.step_target;
  if (!aim.aims()) {
    return build_once({});
  }
  // Mass scaling first; where it would add too much, the shortest bars are collapsed, ever longer
  // ones, until what is left can be scaled within the limit.
  const double step = aimed_step(scene);
  std::vector<double> added;  // the fraction each weld floor needed
  // A floor no higher than every object's own weld builds the same model as the first try.
  double least_weld = 1.0;
  for (const ObjectDesc& object : scene.objects) {
    least_weld = std::min(least_weld, object.weld_fraction);
  }
  for (const double weld : kWeldFloors) {
    if (weld != kWeldFloors.front() && weld <= least_weld) {
      continue;
    }
    Model model = build_once({weld, step});
    if (model.mass_scaling.added_fraction() <= aim.max_added_mass) {
      return model;
    }
    added.push_back(model.mass_scaling.added_fraction());
  }
  // What the strongest collapse with the default's mass scaling reaches, as a step to aim at.
  const Model best = build_once({kWeldFloors.back(), std::nullopt});
  throw_user_error(aim.loc,
                   "a step of {:.3g} s would need {:.3g} % more mass even with the bars shorter "
                   "than {:g} of the median collapsed ({:.3g} % without collapsing), above "
                   "'max_added_mass' {:g} %: the bars are too stiff throughout, not only a few "
                   "short ones. Aim at a step of at most about {:.3g} s (what that collapse "
                   "allows), raise 'max_added_mass', or soften the material",
                   step, 100.0 * added.back(), kWeldFloors.back(), 100.0 * added.front(),
                   100.0 * aim.max_added_mass,
                   kAutoTimestepSafety * 2.0 / std::sqrt(max_frequency_squared_bound(best)));
}

}  // namespace dinam
