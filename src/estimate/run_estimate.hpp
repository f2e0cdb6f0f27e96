#pragma once
// How long a run will take: the steps it needs times the cost of one step, estimated from what
// the model holds (estimate/step_cost.hpp), so that the answer is the same on a quiet machine and
// on a busy one. Contact that starts later, tearing and plastic flow change the cost as the run
// goes, so the figure is an estimate of the simulation, not a promise; drawing the frames comes
// on top.
#include <string>

#include "dynamics/stability.hpp"
#include "estimate/implicit_cost.hpp"
#include "estimate/step_cost.hpp"

namespace dinam {

struct Model;
struct SceneDescription;
struct StepperKind;

// Runs longer than this are refused unless asked for (`--force`): an hour.
inline constexpr double kLongRunSeconds = 3600.0;

struct RunEstimate {
  long long steps = 0;         // over the frames, and those settling may be expected to take
  long long settle_steps = 0;  // of those, the settling's (dynamics/relaxation.hpp)
  StepCost step;               // a step's estimated cost on the threads in use
  ImplicitStepCost implicit;   // what that step is made of, for the implicit integrator
  double seconds = 0.0;        // steps × step.seconds

  bool long_run() const { return seconds > kLongRunSeconds; }
};

// The steps of the whole run: every frame's and, with `settle`, at most its duration's.
long long steps_in_all(const SceneDescription& scene, const Model& model, const TimeStep& timestep);

// The estimate for `threads` threads.
RunEstimate estimate_run(const SceneDescription& scene, const Model& model,
                         const TimeStep& timestep, int threads);
// The same for `kind` in place of the model's own integrator (`dinam info` weighs the other one).
RunEstimate estimate_run(const SceneDescription& scene, const Model& model, const StepperKind& kind,
                         const TimeStep& timestep, int threads);

// Central differences' step's time on this machine as busy as it is now (where the model's kind
// says its step can be timed: IntegratorEstimate::step_can_be_timed): the model stepped from its
// mesh positions (no settling) for about `probe_seconds` or `max_probe_steps` steps, whichever
// comes first. For `info` to print beside the estimate; nothing is decided on it.
struct MeasuredStep {
  double seconds_per_step = 0.0;
  int steps = 0;
};
MeasuredStep measure_step_now(const Model& model, const TimeStep& timestep,
                              double probe_seconds = 0.2, int max_probe_steps = 2000);

// "3.2 s", "17 min", "5.1 h", "12 days".
std::string duration_text(double seconds);

// Throws UserError for a run estimated above kLongRunSeconds unless `force`, at the key to change:
// `settle.duration` when the settling's most steps are the larger part, else the key that sets
// the step (the material of the node that limits it, or the contact stiffness), naming the fixes.
// What `render` and `simulate` check before they start.
void refuse_if_too_long(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                        const RunEstimate& estimate, bool force);

}  // namespace dinam
