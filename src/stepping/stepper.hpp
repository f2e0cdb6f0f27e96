#pragma once
// The one seam between a run and its integrator. A run (run/frame_source.cpp) starts a stepper,
// advances it a number of steps at a time and reads the state between; what a step is — central
// differences' leapfrog, or a Newton solve of backward Euler or BDF2 — is the stepper's. The
// integrators are described once each (stepper_kind.hpp: the stepper, its step, its start, its
// cost), so nothing above this folder branches on the integrator.
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Whether a stepper's start runs the model's settling phase (solver/settle.hpp), or starts from
// the mesh as it is (to measure a step's cost, say).
enum class Settling { kRun, kSkip };

class Stepper {
 public:
  virtual ~Stepper() = default;

  // The state at t = 0: the model's start, settled under gravity first (with kRun, where the
  // model has a settling phase), ready for advance(). With `track_energy`, every step also keeps
  // the energy accounts and report (at some cost), and the report is made here for t = 0.
  virtual State start(bool track_energy, Settling settling = Settling::kRun) = 0;

  // Advances `state` by `steps` steps of the run's step. Throws Interrupted (core/stop_request.hpp)
  // when a signal asks to stop, RuntimeError where the integration fails.
  virtual void advance(State& state, std::int64_t steps) = 0;

  // The nodes' velocities at the state's time t_n, m/s, into `v` (n_nodes), for what reads the
  // motion between steps (State::velocity is the stepper's own: leapfrog keeps v_{n−½}). The
  // state's force array may be used as scratch; the motion that follows is unchanged.
  virtual void velocity_now(State& state, std::vector<Vec3>& v) const = 0;

  const TimeStep& timestep() const { return timestep_; }

 protected:
  Stepper(const Model& model, const TimeStep& timestep) : model_(model), timestep_(timestep) {}

  const Model& model_;
  TimeStep timestep_;
};

}  // namespace dinam
