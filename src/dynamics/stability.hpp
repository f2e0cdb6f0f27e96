#pragma once
// The central-difference method is stable only while Δt < 2 / ω_max, ω_max the highest natural
// frequency of the model. We bound ω_max from above without any eigen-solve (below), so the
// step we call critical is safe.
#include <optional>

#include "core/error.hpp"
#include "model/frequency_bound.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

struct Model;

// The stability limit, s: with ω from the frequency bound and ζ = γ / (2ω) from the damping
// bound, the central-difference limit with damping evaluated at the half step,
//   Δt ≤ (2/ω) (√(1 + ζ²) − ζ)   (Belytschko, Liu and Moran, 2000, §6.4),
// which is 2/ω undamped. Infinite when nothing can vibrate.
double critical_timestep(const Model& model);

struct TimeStep {
  double dt = 0.0;          // s, the step in use
  int steps_per_frame = 1;  // frame interval / dt, a whole number
  double critical = 0.0;    // s, the stability limit
  bool automatic = false;
};

// Chooses the step: `auto` (empty `requested`) takes kAutoTimestepSafety × critical; an explicit
// step above the critical one is refused with both numbers, naming `where`. Either way the step
// is shortened, if needed, so that a whole number of steps fills each frame.
TimeStep choose_timestep(const Model& model, std::optional<double> requested, double fps,
                         const FileLoc& where);
// The same for `integrator` in place of the model's own (`dinam info` weighs the other one).
TimeStep choose_timestep(const Model& model, IntegratorKind integrator,
                         std::optional<double> requested, double fps, const FileLoc& where);

}  // namespace dinam
