#include "estimate/run_estimate.hpp"

#include "estimate/integrator_choice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/relaxation.hpp"
#include "estimate/integrator_estimates.hpp"
#include "model/model.hpp"
#include "model/step_limits.hpp"
#include "scene/scene_description.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

namespace dinam {

namespace {

// The most steps settling may take: its duration's.
long long settle_steps(const Model& model, const TimeStep& timestep) {
  return model.settle.enabled ? std::llround(model.settle.duration / timestep.dt) : 0;
}

// The steps settling may be expected to take: relaxation's (Newton's method settles a structure
// that is stable on the way without a step, and one that buckles after relaxation).
long long expected_settle_steps(const Model& model, const TimeStep& timestep) {
  return model.settle.enabled ? std::llround(expected_relaxation_seconds(model) / timestep.dt) : 0;
}

}  // namespace

long long steps_in_all(const SceneDescription& scene, const Model& model,
                       const TimeStep& timestep) {
  return static_cast<long long>(scene.frame_count()) * timestep.steps_per_frame +
         settle_steps(model, timestep);
}

RunEstimate estimate_run(const SceneDescription& scene, const Model& model,
                         const TimeStep& timestep, int threads) {
  return estimate_run(scene, model, stepper_kind(model), timestep, threads);
}

RunEstimate estimate_run(const SceneDescription& scene, const Model& model, const StepperKind& kind,
                         const TimeStep& timestep, int threads) {
  RunEstimate estimate;
  estimate.settle_steps = expected_settle_steps(model, timestep);
  estimate.steps =
      steps_in_all(scene, model, timestep) - settle_steps(model, timestep) + estimate.settle_steps;
  integrator_estimate(kind).estimate_steps(scene, model, threads, estimate);
  estimate.seconds = estimate.step.seconds * static_cast<double>(estimate.steps);
  return estimate;
}

MeasuredStep measure_step_now(const Model& model, const TimeStep& timestep, double probe_seconds,
                              int max_probe_steps) {
  MeasuredStep measured;
  State state = initial_state(model, timestep.dt, {}, false, Settling::kSkip);
  step(model, timestep.dt, {}, state);  // the first step touches every array once: not timed
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (measured.steps < std::max(max_probe_steps, 1) && elapsed < probe_seconds) {
    step(model, timestep.dt, {}, state);
    ++measured.steps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  measured.seconds_per_step = elapsed / measured.steps;
  return measured;
}

std::string duration_text(double seconds) {
  if (seconds < 60.0) {
    return fmt::format("{:.2g} s", seconds);
  }
  if (seconds < 3600.0) {
    return fmt::format("{:.0f} min", seconds / 60.0);
  }
  if (seconds < 48 * 3600.0) {
    return fmt::format("{:.1f} h", seconds / 3600.0);
  }
  return fmt::format("{:.0f} days", seconds / 86400.0);
}

void refuse_if_too_long(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                        const RunEstimate& estimate, bool force) {
  // The estimate counts the settling it expects; its duration is the most it may take, which is
  // refused as well when that alone would pass the limit.
  const long long settle_cap = settle_steps(model, timestep);
  const double capped_seconds =
      estimate.seconds +
      static_cast<double>(settle_cap - estimate.settle_steps) * estimate.step.seconds;
  if (force || (!estimate.long_run() && capped_seconds <= kLongRunSeconds)) {
    return;
  }
  const std::string cost = fmt::format(
      "would take {} ({:.3g} ms a step on {} thread{}, estimated from the model's springs "
      "and nodes), more than {}",
      estimate.long_run() ? "about " + duration_text(estimate.seconds)
                          : "up to " + duration_text(capped_seconds),
      1e3 * estimate.step.seconds, estimate.step.threads, estimate.step.threads == 1 ? "" : "s",
      duration_text(kLongRunSeconds));
  // Settling that may run longer than the motion itself: its duration is the key to change.
  const long long steps_at_most = estimate.steps - estimate.settle_steps + settle_cap;
  if (2 * settle_cap > steps_at_most) {
    throw_user_error(scene.settle.duration_loc,
                     "settling may take {} steps of {:.3g} s (its 'duration' of {:g} s is the "
                     "longest it runs before the structure rests) and the run {}; give "
                     "'settle.duration' a few times the structure's slowest period (a few "
                     "seconds for most scenes), or pass --force to run it anyway",
                     settle_cap, timestep.dt, scene.settle.duration, cost);
  }
  const StepLimits limits = find_step_limits(model);
  std::string cause;
  FileLoc key = scene.duration_loc;  // when no one node limits the step
  if (limits.fastest_node >= 0) {
    const ObjectDesc& object = scene.objects[model.node_object[limits.fastest_node]];
    if (limits.contact_dominates) {
      cause = fmt::format(" (the contact penalty at {} sets it)",
                          describe_node(model, limits.fastest_node));
      const FileLoc& stiffness = scene.ground.stiffness_loc.known() ? scene.ground.stiffness_loc
                                                                    : scene.contact.stiffness_loc;
      key = stiffness.known() ? stiffness : scene.duration_loc;
    } else {
      cause =
          fmt::format(" (set by {}, whose shortest bar is {:.3g} m; the median bar is {:.3g} m)",
                      describe_node(model, limits.fastest_node), limits.shortest_at_fastest,
                      limits.median_length);
      key = object.material.loc;
    }
  }
  // The step that would bring the run within the limit, as a `max_steps`.
  const auto max_steps = static_cast<long long>(
      std::floor(static_cast<double>(steps_at_most) * kLongRunSeconds / capped_seconds));
  // Another integrator, where `info` would recommend one: first, since it keeps the material.
  const IntegratorChoice choice = compare_integrators(scene, model, estimate.step.threads, false);
  std::string other;
  if (choice.recommended != &stepper_kind(model)) {
    const RunEstimate& recommended = choice.recommends_xpbd()       ? choice.xpbd
                                     : choice.recommends_implicit() ? choice.implicit
                                                                    : choice.central_difference;
    other = fmt::format("use 'integrator: {}' (about {}: {}), ", recommended_key(choice),
                        duration_text(recommended.seconds), recommendation_reason(choice));
  }
  throw_user_error(key,
                   "this run of {:g} s needs {} steps of {:.3g} s{} and {}; {}aim the step with "
                   "'timestep: {{max_steps: {}}}' (mass scaling and collapsing the shortest bars), "
                   "collapse short bars with 'mesh: {{weld: 0.1}}', use a softer material, or "
                   "pass --force to run it anyway",
                   scene.duration, steps_at_most, timestep.dt, cause, cost, other, max_steps);
}

}  // namespace dinam
