#pragma once
// How long a run will take on this machine: the steps it needs times the cost of one step,
// measured by running a few steps of the model (a probe of a fraction of a second). Contact that
// starts later, tearing and plastic flow change the cost as the run goes, so the figure is an
// estimate of the simulation, not a promise; drawing the frames comes on top.
#include <filesystem>
#include <string>

#include "dynamics/stability.hpp"

namespace dinam {

struct Model;
struct SceneDescription;

// Runs longer than this are refused unless asked for (`--force`): an hour.
inline constexpr double kLongRunSeconds = 3600.0;

struct RunEstimate {
  long long steps = 0;            // over the frames, and the most that settling may take
  double seconds_per_step = 0.0;  // measured
  int probe_steps = 0;            // steps the measurement ran
  double seconds = 0.0;           // steps × seconds_per_step

  bool long_run() const { return seconds > kLongRunSeconds; }
};

// The steps of the whole run: every frame's and, with `settle`, at most its duration's.
long long steps_in_all(const SceneDescription& scene, const Model& model, const TimeStep& timestep);

// Steps the model (from its initial state) for about `probe_seconds` of wall time or
// `max_probe_steps`, whichever comes first, and scales the cost to the whole run. With
// `enough_below` > 0 it stops as soon as, after a few steps, the run is sure to take less than
// that (s): all `render` and `simulate` need to know.
RunEstimate estimate_run_time(const SceneDescription& scene, const Model& model,
                              const TimeStep& timestep, double probe_seconds = 0.2,
                              int max_probe_steps = 2000, double enough_below = 0.0);

// The check `render` and `simulate` make before they start: refuse_if_too_long on a quick probe.
void refuse_long_run(const std::filesystem::path& scene_path, const SceneDescription& scene,
                     const Model& model, const TimeStep& timestep, bool force);

// "3.2 s", "17 min", "5.1 h", "12 days".
std::string duration_text(double seconds);

// Throws UserError for a run estimated above kLongRunSeconds unless `force`, naming what limits
// the step and the fixes.
void refuse_if_too_long(const std::filesystem::path& scene_path, const Model& model,
                        const TimeStep& timestep, const RunEstimate& estimate, bool force);

}  // namespace dinam
