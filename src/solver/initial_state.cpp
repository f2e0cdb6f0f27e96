#include "solver/initial_state.hpp"

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "solver/settle.hpp"

namespace dinam {

double settling_step(const Model& model, double dt) {
  return model.integrator == IntegratorKind::kImplicit
             ? kAutoTimestepSafety * critical_timestep(model)
             : dt;
}

State initial_state(const Model& model, double dt, const ForceSwitches& switches, bool track_energy,
                    Settling settling) {
  State state = make_state(model, track_energy);
  if (settling == Settling::kRun) {
    settle_under_gravity(model, settling_step(model, dt), switches, state);
  }
  if (model.integrator == IntegratorKind::kCentralDifference) {
    start_leapfrog(model, dt, switches, state);
  }
  return state;
}

}  // namespace dinam
