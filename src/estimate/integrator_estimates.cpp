#include "estimate/integrator_estimates.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "dynamics/contact/object_contact_implicit.hpp"
#include "estimate/implicit_cost.hpp"
#include "estimate/run_estimate.hpp"
#include "estimate/solver_memory.hpp"
#include "estimate/step_cost.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/stepper_kind.hpp"

namespace dinam {
namespace {

std::string leapfrog_run_time_note(const Model&, const RunEstimate& estimate) {
  const StepCost& cost = estimate.step;
  return fmt::format(
      "about {} to simulate ({:.3g} ms a step on {} thread{}, estimated from the model's springs "
      "and nodes; drawing comes on top){}",
      duration_text(estimate.seconds), 1e3 * cost.seconds, cost.threads,
      cost.threads == 1 ? "" : "s",
      estimate.long_run() ? fmt::format("; over {}, so render and simulate refuse it without "
                                        "--force",
                                        duration_text(kLongRunSeconds))
                          : "");
}

// A Newton solve a step (implicit_cost.hpp), on one thread: the factorisation is.
void implicit_estimate_steps(const SceneDescription& scene, const Model& model, int /*threads*/,
                             RunEstimate& estimate) {
  estimate.implicit = estimate_implicit_step(model, estimate_step_cost(model, 1));
  double seconds = estimate.implicit.seconds;
  // Contact between objects splits the steps where a node would pass its speed envelope; the
  // steps split off are short, and cost what a short step does.
  const double frames_seconds = static_cast<double>(scene.frame_count()) / scene.fps;
  const auto envelope_steps =
      static_cast<long long>(std::ceil(contact_envelope_steps(model, frames_seconds)));
  const long long split_off = envelope_steps + estimate.settle_steps - estimate.steps;
  if (split_off > 0) {
    const auto steps = static_cast<double>(estimate.steps);
    seconds =
        (steps * seconds + static_cast<double>(split_off) * estimate.implicit.short_step_seconds) /
        (steps + static_cast<double>(split_off));
    estimate.steps += split_off;
  }
  estimate.step = {.parts = {{"Newton iterations and factorisations", 1.0, 1e9 * seconds}},
                   .serial_ns = 1e9 * seconds,
                   .threads = 1,
                   .seconds = seconds};
}

std::string implicit_run_time_note(const Model&, const RunEstimate& estimate) {
  return fmt::format(
      "about {} to simulate ({:.3g} ms a step, a Newton solve, estimated from the model's "
      "springs and the size of its Hessian's factor; drawing comes on top)",
      duration_text(estimate.seconds), 1e3 * estimate.step.seconds);
}

// The state is all central differences hold.
std::uint64_t no_workspace(const Model&) {
  return 0;
}

const std::array<IntegratorEstimate, 3> kIntegratorEstimates = {{
    {.kind = &kCentralDifferences,
     .estimate_steps =
         [](const SceneDescription&, const Model& model, int threads, RunEstimate& estimate) {
           estimate.step = estimate_step_cost(model, threads);
         },
     .workspace_bytes = no_workspace,
     .step_can_be_timed = true,
     .run_time_note = leapfrog_run_time_note},
    // The bars as constraints: the kinds held cost their projection's sweeps (step_cost.hpp).
    {.kind = &kBarConstraints,
     .estimate_steps =
         [](const SceneDescription&, const Model& model, int threads, RunEstimate& estimate) {
           estimate.step = estimate_step_cost(model, threads, true);
         },
     .workspace_bytes = no_workspace,
     .step_can_be_timed = true,
     .run_time_note = leapfrog_run_time_note},
    {.kind = &kImplicitSchemes,
     .estimate_steps = implicit_estimate_steps,
     .workspace_bytes = implicit_integrator_bytes,
     .step_can_be_timed = false,
     .run_time_note = implicit_run_time_note},
}};

}  // namespace

const IntegratorEstimate& integrator_estimate(const StepperKind& kind) {
  for (const IntegratorEstimate& entry : kIntegratorEstimates) {
    if (entry.kind == &kind) {
      return entry;
    }
  }
  DINAM_CHECK(false && "an integrator without its estimates (integrator_estimates.cpp)");
  return kIntegratorEstimates[0];
}

}  // namespace dinam
