#include "stepping/central_difference_stepper.hpp"

#include "stepping/time_step.hpp"

namespace dinam {

State CentralDifferenceStepper::start(bool track_energy, Settling settling) {
  return initial_state(model_, timestep_.dt, {}, track_energy, settling);
}

void CentralDifferenceStepper::advance(State& state, std::int64_t steps) {
  advance_steps(model_, timestep_.dt, {}, state, steps);
}

}  // namespace dinam
