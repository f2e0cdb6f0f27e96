#include "dynamics/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "model/frequency_bound.hpp"
#include "model/model.hpp"

namespace dinam {

double critical_timestep(const Model& model, BarsIn bars) {
  return critical_timestep_of(max_frequency_squared_bound(model, true, bars),
                              max_damping_rate_bound(model, bars));
}

double critical_timestep_of(double omega_squared, double gamma) {
  if (omega_squared <= 0.0) {
    // Pure damping: v_{n+½} = (1 − γΔt) v_{n−½} is stable for γΔt < 2.
    return gamma > 0.0 ? 2.0 / gamma : std::numeric_limits<double>::infinity();
  }
  const double omega = std::sqrt(omega_squared);
  const double zeta = gamma / (2.0 * omega);
  return 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

TimeStep choose_explicit_timestep(const Model& model, std::optional<double> requested, double fps,
                                  const FileLoc& where, BarsIn bars) {
  const double critical = critical_timestep(model, bars);
  if (requested && *requested > critical) {
    throw_user_error(where,
                     "the time step {:.6g} s is above this model's stability limit {:.6g} s "
                     "(from its highest frequency and damping); the central-difference "
                     "integration would blow up. "
                     "Use "
                     "'timestep: auto' or a step of at most {:.6g} s",
                     *requested, critical, critical);
  }
  TimeStep step = fit_timestep_to_frames(requested.value_or(kAutoTimestepSafety * critical), fps,
                                         requested, where);
  step.critical = critical;
  step.automatic = !requested.has_value();
  return step;
}

TimeStep fit_timestep_to_frames(double target, double fps, std::optional<double> requested,
                                const FileLoc& where) {
  TimeStep step;
  const double frame_interval = 1.0 / fps;
  // Relative slack so that 0.05 s / 0.0005 s counts as exactly 100 steps despite rounding.
  const double steps = std::ceil(frame_interval / target * (1.0 - 1e-9));
  if (steps > 1e8 && requested) {
    throw_user_error(where,
                     "the time step {:.3g} s would take {:.3g} steps a frame, more than any run "
                     "can; give a step of at least {:.3g} s, or 'timestep: auto'",
                     *requested, steps, frame_interval / 1e8);
  }
  if (steps > 1e8) {
    throw_user_error(where,
                     "this model needs a time step of {:.3g} s, over {:.3g} steps per frame; "
                     "stiffen less (lower youngs_modulus) or make the bars heavier",
                     target, steps);
  }
  step.steps_per_frame = std::max(1, static_cast<int>(steps));
  step.dt = frame_interval / step.steps_per_frame;
  return step;
}

}  // namespace dinam
