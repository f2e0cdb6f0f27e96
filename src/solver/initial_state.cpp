#include "solver/initial_state.hpp"

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "solver/settle.hpp"

namespace dinam {

State initial_state(const Model& model, double dt, const ForceSwitches& switches, bool track_energy,
                    Settling settling) {
  State state = make_state(model, track_energy);
  if (settling == Settling::kRun) {
    // Relaxation steps by central differences: with the implicit integrator's long step, at the
    // automatic explicit one instead.
    const double settle_dt = model.integrator == IntegratorKind::kImplicit
                                 ? kAutoTimestepSafety * critical_timestep(model)
                                 : dt;
    settle_under_gravity(model, settle_dt, switches, state);
  }
  if (model.integrator == IntegratorKind::kCentralDifference) {
    start_leapfrog(model, dt, switches, state);
  }
  return state;
}

}  // namespace dinam
