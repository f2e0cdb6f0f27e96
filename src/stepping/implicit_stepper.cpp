#include "stepping/implicit_stepper.hpp"

#include "stepping/time_step.hpp"

namespace dinam {

State ImplicitStepper::start(bool track_energy, Settling settling) {
  State state = initial_state(integrator_.model(), timestep_.dt, {}, track_energy, settling);
  integrator_.report_energy(state);
  return state;
}

void ImplicitStepper::advance(State& state, std::int64_t steps) {
  integrator_.advance(state, timestep_.dt, steps);
}

}  // namespace dinam
