#include "app/run_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/command_support.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "model/step_limits.hpp"
#include "scene/scene_description.hpp"
#include "solver/initial_state.hpp"

namespace dinam {

long long steps_in_all(const SceneDescription& scene, const Model& model,
                       const TimeStep& timestep) {
  const long long settling =
      model.settle.enabled ? std::llround(model.settle.duration / timestep.dt) : 0;
  return static_cast<long long>(scene.frame_count()) * timestep.steps_per_frame + settling;
}

RunEstimate estimate_run(const SceneDescription& scene, const Model& model,
                         const TimeStep& timestep, int threads) {
  RunEstimate estimate;
  estimate.steps = steps_in_all(scene, model, timestep);
  estimate.step = estimate_step_cost(model, threads);
  estimate.seconds = estimate.step.seconds * static_cast<double>(estimate.steps);
  return estimate;
}

MeasuredStep measure_step_now(const Model& model, const TimeStep& timestep, double probe_seconds,
                              int max_probe_steps) {
  MeasuredStep measured;
  State state = initial_state(model, timestep.dt, {}, false, Settling::kSkip);
  step(model, timestep.dt, {}, state);  // the first step touches every array once: not timed
  const auto start = Clock::now();
  double elapsed = 0.0;
  while (measured.steps < std::max(max_probe_steps, 1) && elapsed < probe_seconds) {
    step(model, timestep.dt, {}, state);
    ++measured.steps;
    elapsed = seconds_since(start);
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

void refuse_if_too_long(const std::filesystem::path& scene_path, const Model& model,
                        const TimeStep& timestep, const RunEstimate& estimate, bool force) {
  if (force || !estimate.long_run()) {
    return;
  }
  const StepLimits limits = find_step_limits(model);
  std::string cause;
  if (limits.fastest_node >= 0) {
    cause = limits.contact_dominates
                ? fmt::format(" (the contact penalty at {} sets it)",
                              describe_node(model, limits.fastest_node))
                : fmt::format(
                      " (set by {}, whose shortest bar is {:.3g} m; the median bar is "
                      "{:.3g} m)",
                      describe_node(model, limits.fastest_node), limits.shortest_at_fastest,
                      limits.median_length);
  }
  // The step that would bring the run within the limit, as a `max_steps`.
  const auto max_steps = static_cast<long long>(
      std::floor(static_cast<double>(estimate.steps) * kLongRunSeconds / estimate.seconds));
  throw_user_error({},
                   "{}: this run needs {} steps of {:.3g} s{} and would take about {} ({:.3g} ms "
                   "a step on {} thread{}, estimated from the model's springs and nodes), more "
                   "than {}; aim the step with "
                   "'timestep: {{max_steps: {}}}' (mass scaling and collapsing the shortest bars), "
                   "collapse short bars with 'mesh: {{weld: 0.1}}', use a softer material, or "
                   "pass --force to run it anyway",
                   scene_path.string(), estimate.steps, timestep.dt, cause,
                   duration_text(estimate.seconds), 1e3 * estimate.step.seconds,
                   estimate.step.threads, estimate.step.threads == 1 ? "" : "s",
                   duration_text(kLongRunSeconds), max_steps);
}

}  // namespace dinam
