#pragma once
// What the estimates need of each integrator, one entry per integrator as stepping/stepper_kind.hpp
// describes the integrators themselves: a step's cost, the memory its stepper holds beside the
// state, whether `info` can time its step, and the words of `info`'s "run time" line. Each entry
// sits in integrator_estimates.cpp, so every estimate is in this folder; integrator_estimate()
// finds a kind's entry (a lookup, not a branch on the integrator).
//
// A new integrator adds its entry here beside its StepperKind.
#include <cstdint>
#include <string>

namespace dinam {

struct Model;
struct RunEstimate;
struct SceneDescription;
struct StepperKind;

struct IntegratorEstimate {
  const StepperKind* kind;
  // A run's cost (run_estimate.hpp): a step's, into `estimate.step`, and any steps it expects to
  // add to `estimate.steps` (the implicit schemes' split steps), for `threads` threads.
  void (*estimate_steps)(const SceneDescription&, const Model&, int threads, RunEstimate&);
  // Bytes its stepper holds beside the state at its peak (the implicit schemes' Hessian and
  // factor: solver_memory.hpp), which the memory estimate counts.
  std::uint64_t (*workspace_bytes)(const Model&);
  // Whether measure_step_now (run_estimate.hpp) times its step: central differences' step is
  // cheap and regular; an implicit step is a Newton solve, which the probe does not measure.
  bool step_can_be_timed;
  // `dinam info`'s "run time": the estimate and what it is made of.
  std::string (*run_time_note)(const Model&, const RunEstimate&);
};

// The entry of `kind` (one of stepping/stepper_kind.hpp's kinds).
const IntegratorEstimate& integrator_estimate(const StepperKind& kind);

}  // namespace dinam
