#pragma once
// The one seam between a run and its integrator. A run (run/frame_source.cpp) starts a stepper,
// advances it a number of steps at a time and reads the state between; what a step is — central
// differences' leapfrog, or a Newton solve of backward Euler or BDF2 — is the stepper's. The
// integrator kinds are mapped to their steppers, step choices and cost estimates in this folder
// alone (integrator_kinds.cpp), so nothing above it branches on the integrator.
#include <cstdint>
#include <memory>

#include "dynamics/integrator.hpp"
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

  const TimeStep& timestep() const { return timestep_; }

 protected:
  Stepper(const Model& model, const TimeStep& timestep) : model_(model), timestep_(timestep) {}

  const Model& model_;
  TimeStep timestep_;
};

// The stepper of the model's integrator (model.integrator) at `timestep` (choose_timestep).
std::unique_ptr<Stepper> make_stepper(const Model& model, const TimeStep& timestep);

// Whether the model's stepper holds a copy of the model (the implicit schemes' with the ground
// softened), which a memory estimate counts.
bool stepper_copies_model(const Model& model);

}  // namespace dinam
