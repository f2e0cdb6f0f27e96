#include "solver/initial_state.hpp"

#include "solver/settle.hpp"

namespace dinam {

State initial_state(const Model& model, double dt, const ForceSwitches& switches, bool track_energy,
                    Settling settling) {
  State state = make_state(model, track_energy);
  if (settling == Settling::kRun) {
    settle_under_gravity(model, dt, switches, state);
  }
  start_leapfrog(model, dt, switches, state);
  return state;
}

}  // namespace dinam
