#pragma once
// The settling phase before t = 0 (SettlePhase): the structure hangs or rests under gravity alone
// until its motion has died away, and the shape it reaches becomes the start of the shown motion.
// Fields, wind and initial velocities wait until t = 0; plastic sets and ground contact history
// carry over, so a structure that yields under its own weight keeps that set.
#include <cstdint>

#include "dynamics/state.hpp"

namespace dinam {

struct Model;
struct ForceSwitches;

// Dynamic relaxation: `steps` steps from `state`, with every velocity zeroed whenever the kinetic
// energy passes a peak, which walks the structure down to a static equilibrium of the forces that
// `switches` leave on (plastic sets and contact history evolve as in any step).
void relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                              std::int64_t steps, State& state);

// Runs the phase from `state` (at the mesh positions, at rest) for model.settle.duration with
// steps of dt, leaving positions and histories in `state`. Does nothing without a phase.
void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state);

}  // namespace dinam
