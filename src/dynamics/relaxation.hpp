#pragma once
// The settling phase before t = 0 (SettlePhase): the structure hangs or rests under gravity alone
// until it is in static equilibrium, and the shape it reaches becomes the start of the shown
// motion. Fields, wind and initial velocities wait until t = 0; plastic sets and ground contact
// history carry over, so a structure that yields under its own weight keeps that set.
#include <cstdint>

#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// The largest out-of-balance force on a free node relative to that node's weight m |g| (standard
// gravity where the model has none), from the forces in state.force, and the node it is on.
std::pair<double, Index> relative_residual(const Model& model, const State& state);

// Dynamic relaxation by kinetic damping: from `state`, at most `max_steps` steps; whenever the
// kinetic energy has passed a peak, the motion restarts from rest where it is. Each restart
// removes the energy near a point of lowest potential, so the structure walks down to a static
// equilibrium of the forces that `switches` leave on (plastic sets and contact history evolve as
// in any step). Stops at the first restart whose out-of-balance force is at most `residual` of the
// weight (0: never, run all the steps); positions and histories are left in `state`.
SettleOutcome relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                                       std::int64_t max_steps, double residual, State& state,
                                       const StepOptions& options = {});

// The viscous damping of the settling phase's first stage when the scene leaves it to dinam:
// α = 8 √(g / D), D the size (bounding-box diagonal) of the free nodes, four times critical for
// the slowest swing of the whole structure (ω ≈ √(g / D)), so that it creeps down instead.
double automatic_settle_damping(const Model& model);

// Viscous dynamic relaxation: at most `max_steps` steps of the model with `options` and global
// damping `damping` (1/s) instead of its own, until the out-of-balance force is at most `handover`
// of the weight (checked every 100 steps). Returns the steps taken; the residual is in `outcome`.
std::int64_t relax_viscously(const Model& model, double dt, const ForceSwitches& switches,
                             const StepOptions& options, double damping, std::int64_t max_steps,
                             double handover, State& state, SettleOutcome& outcome);

// Runs the phase from `state` (at the mesh positions, at rest) with steps of dt: overdamped
// viscous relaxation (model.settle.damping, automatic_settle_damping when empty; 0 skips it) until
// every node carries 90 % of its weight, then kinetic damping until it reaches
// model.settle.residual, leaving positions and histories in `state` and the outcome in
// state.settled. Does nothing without a phase. Throws UserError at the scene's `settle` when it
// has not converged within model.settle.duration.
void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state);

}  // namespace dinam
