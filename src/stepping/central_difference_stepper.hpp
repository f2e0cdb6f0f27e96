#pragma once
// Central differences (the paper's method): leapfrog, explicit, its step bounded by the stiffest
// spring (dynamics/stability.hpp). State::velocity is v_{n−½}. Its entry, kCentralDifferences,
// is in stepper_kind.hpp.
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
  // v_n = v_{n−½} + ½Δt a_n, a_n from the forces at x_n (the velocity-dependent ones at v_{n−½}):
  // the start's half step undone.
  void velocity_now(State& state, std::vector<Vec3>& v) const override;
};

// How well central differences' energy report balances at the run's step (see the .cpp), which
// `dinam info` prints whatever the integrator.
struct EnergyBalanceGuide {
  double omega_dt = 0.0;      // ω_max Δt, ω_max the stability bound's
  double balance = 0.0;       // expected worst |total − start| / peak kinetic energy
  double step_for_0_1 = 0.0;  // s, the step that brings it to 0.1 %
};
EnergyBalanceGuide energy_balance_guide(const Model& model, const TimeStep& timestep);

}  // namespace dinam
