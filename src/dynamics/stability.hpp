#pragma once
// The central-difference method is stable only while Δt < 2 / ω_max, ω_max the highest natural
// frequency of the model. We bound ω_max from above without any eigen-solve (below), so the
// step we call critical is safe.
#include <optional>

#include "core/error.hpp"
#include "model/frequency_bound.hpp"

namespace dinam {

struct Model;

// The stability limit, s: with ω from the frequency bound and ζ = γ / (2ω) from the damping
// bound, the central-difference limit with damping evaluated at the half step,
//   Δt ≤ (2/ω) (√(1 + ζ²) − ζ)   (Belytschko, Liu and Moran, 2000, §6.4),
// which is 2/ω undamped. Infinite when nothing can vibrate.
// `bars` as the bound counts them (frequency_bound.hpp).
double critical_timestep(const Model& model, BarsIn bars = BarsIn::kTheModelsWay);
// The same limit from the bounds themselves: ω² (rad²/s²) and γ (1/s).
double critical_timestep_of(double omega_squared, double gamma);

struct TimeStep {
  double dt = 0.0;          // s, the step in use
  int steps_per_frame = 1;  // frame interval / dt, a whole number
  double critical = 0.0;    // s, the stability limit
  bool automatic = false;
};

// Central differences' step: `auto` (empty `requested`) takes kAutoTimestepSafety × critical; an
// explicit step above the critical one is refused with both numbers, naming `where`. Either way
// the step is fitted to the frames (fit_timestep_to_frames). stepping/time_step.hpp chooses the
// step of whichever integrator the model has.
TimeStep choose_explicit_timestep(const Model& model, std::optional<double> requested, double fps,
                                  const FileLoc& where, BarsIn bars = BarsIn::kTheModelsWay);

// A step of at most `target` s, shortened so that a whole number of steps fills each frame; a
// step that would take more than 10⁸ steps a frame is refused at `where` (the `requested` one, or
// the model's). `critical` and `automatic` are left for the caller.
TimeStep fit_timestep_to_frames(double target, double fps, std::optional<double> requested,
                                const FileLoc& where);

}  // namespace dinam
