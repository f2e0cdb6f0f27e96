#pragma once
// The implicit schemes (backward Euler, BDF2: solver/implicit_integrator.hpp): each step a
// minimisation by Newton's method, stable at any step. State::velocity holds v_n, not leapfrog's
// v_{n−½}. Their entry, kImplicitSchemes, is in stepper_kind.hpp.
#include "solver/implicit_integrator.hpp"
#include "stepping/stepper.hpp"

namespace dinam {

class ImplicitStepper final : public Stepper {
 public:
  // The ground softened for the run's step (ImplicitOptions).
  ImplicitStepper(const Model& model, const TimeStep& timestep)
      : Stepper(model, timestep), integrator_(model, {.longest_step = timestep.dt}) {}

  // v_0 itself; the settling phase relaxes by the automatic explicit step (the entry's
  // settling_step), the run's being far longer than relaxation can take.
  State start(bool track_energy, Settling settling = Settling::kRun) override;
  void advance(State& state, std::int64_t steps) override;
  // State::velocity itself.
  void velocity_now(State& state, std::vector<Vec3>& v) const override;

  const ImplicitStats& stats() const { return integrator_.stats(); }

 private:
  ImplicitIntegrator integrator_;
};

}  // namespace dinam
