#pragma once
// The step a run takes, and the state it starts from, for the model's integrator (its kind's,
// stepper_kind.hpp).
#include <optional>

#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/state.hpp"
#include "stepping/stepper.hpp"

namespace dinam {

struct Model;

// Central differences: `auto` (empty `requested`) takes kAutoTimestepSafety × the stability
// limit; a step above the limit is refused with both numbers, naming `where`. The implicit
// schemes: `requested`, by default a quarter of a frame, stable at any step. Either way the step
// is shortened, if needed, so that a whole number of steps fills each frame.
TimeStep choose_timestep(const Model& model, std::optional<double> requested, double fps,
                         const FileLoc& where);

// The step the settling phase relaxes by (solver/settle.hpp): the run's `dt` under central
// differences; under the implicit schemes, whose steps are far longer than relaxation can take,
// the automatic explicit step instead.
double settling_step(const Model& model, double dt);

// The state at t = 0, as the model's stepper starts it (Stepper::start), with `switches` for the
// forces of the settling phase and of leapfrog's first half step (tests turn some off).
State initial_state(const Model& model, double dt, const ForceSwitches& switches = {},
                    bool track_energy = false, Settling settling = Settling::kRun);

}  // namespace dinam
