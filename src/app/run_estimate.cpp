#include "app/run_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/command_support.hpp"
#include "app/step_limits.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

// Steps timed before a quick probe may decide; a fourfold margin covers their noise.
constexpr int kFewSteps = 5;

}  // namespace

long long steps_in_all(const SceneDescription& scene, const Model& model,
                       const TimeStep& timestep) {
  const long long settling =
      model.settle.enabled ? std::llround(model.settle.duration / timestep.dt) : 0;
  return static_cast<long long>(scene.frame_count()) * timestep.steps_per_frame + settling;
}

RunEstimate estimate_run_time(const SceneDescription& scene, const Model& model,
                              const TimeStep& timestep, double probe_seconds, int max_probe_steps,
                              double enough_below) {
  RunEstimate estimate;
  estimate.steps = steps_in_all(scene, model, timestep);
  State state = initial_state(model, timestep.dt);
  step(model, timestep.dt, {}, state);  // the first step touches every array once: not timed
  const auto start = Clock::now();
  double elapsed = 0.0;
  const int most = static_cast<int>(std::min<long long>(max_probe_steps, estimate.steps));
  while (estimate.probe_steps < std::max(most, 1)) {
    step(model, timestep.dt, {}, state);
    ++estimate.probe_steps;
    elapsed = seconds_since(start);
    const bool sure_below =
        enough_below > 0.0 && estimate.probe_steps >= kFewSteps &&
        elapsed / estimate.probe_steps * static_cast<double>(estimate.steps) < 0.25 * enough_below;
    if (elapsed >= probe_seconds || sure_below) {
      break;
    }
  }
  estimate.seconds_per_step = elapsed / estimate.probe_steps;
  estimate.seconds = estimate.seconds_per_step * static_cast<double>(estimate.steps);
  return estimate;
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
                   "{}: this run needs {} steps of {:.3g} s{} and would take about {} on this "
                   "machine ({:.3g} ms a step, measured), more than {}; aim the step with "
                   "'timestep: {{max_steps: {}}}' (mass scaling and collapsing the shortest bars), "
                   "collapse short bars with 'mesh: {{weld: 0.1}}', use a softer material, or "
                   "pass --force to run it anyway",
                   scene_path.string(), estimate.steps, timestep.dt, cause,
                   duration_text(estimate.seconds), 1e3 * estimate.seconds_per_step,
                   duration_text(kLongRunSeconds), max_steps);
}

void refuse_long_run(const std::filesystem::path& scene_path, const SceneDescription& scene,
                     const Model& model, const TimeStep& timestep, bool force) {
  if (force) {
    return;
  }
  refuse_if_too_long(scene_path, model, timestep,
                     estimate_run_time(scene, model, timestep, 0.2, 2000, kLongRunSeconds), force);
}

}  // namespace dinam
