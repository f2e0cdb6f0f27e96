#pragma once
// Central differences (the paper's method): leapfrog, explicit, its step bounded by the stiffest
// spring (dynamics/stability.hpp). State::velocity is v_{n−½}.
#include "stepping/stepper.hpp"

namespace dinam {

class CentralDifferenceStepper final : public Stepper {
 public:
  CentralDifferenceStepper(const Model& model, const TimeStep& timestep)
      : Stepper(model, timestep) {}

  // The settled start, and v_{−½} = v_0 − ½Δt a_0, so that the first half-step velocity is
  // v_{½} = v_0 + ½Δt a_0.
  State start(bool track_energy, Settling settling = Settling::kRun) override;
  void advance(State& state, std::int64_t steps) override;
};

}  // namespace dinam
