#pragma once
// Dynamic relaxation: the way the settling phase (solver/settle.hpp) comes to rest when Newton's
// method cannot serve (`settle: {method: relax}`, or friction, yielding or tearing on the way):
// the structure is stepped in time, overdamped and then by kinetic damping, until the static
// out-of-balance force is small enough. Plastic sets and ground contact history evolve as in any
// step, so a structure that yields under its own weight keeps that set.
#include <cstdint>
#include <functional>

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
// weight (0: never, run all the steps), or at the first restart where `stop` (if given) returns
// true for the state at rest there (outcome.stopped); positions and histories are left in `state`,
// the static forces in state.force.
using RestartTest = std::function<bool(const State&)>;
SettleOutcome relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                                       std::int64_t max_steps, double residual, State& state,
                                       const StepOptions& options = {},
                                       const RestartTest& stop = {});

// The viscous damping of the settling phase's first stage when the scene leaves it to dinam:
// α = 8 √(g / D), D the size (bounding-box diagonal) of the free nodes, four times critical for
// the slowest swing of the whole structure (ω ≈ √(g / D)), so that it creeps down instead.
double automatic_settle_damping(const Model& model);

// How long relaxation may be expected to run, for a run's estimate (not a limit: that is
// model.settle.duration, which caps this): the creep's time constant for the slowest swing,
// τ = α D / g (α the creep's damping, 8 √(g / D) when automatic), 2.3 τ for the structure to take
// 90 % of its weight, and kinetic damping about as long again. The paper's flag relaxes for
// 12.5 s, where this gives 15 s.
double expected_relaxation_seconds(const Model& model);

// Viscous dynamic relaxation: at most `max_steps` steps of the model with `options` and global
// damping `damping` (1/s) instead of its own, until the out-of-balance force is at most `handover`
// of the weight (checked every 100 steps). Returns the steps taken; the residual is in `outcome`.
std::int64_t relax_viscously(const Model& model, double dt, const ForceSwitches& switches,
                             const StepOptions& options, double damping, std::int64_t max_steps,
                             double handover, State& state, SettleOutcome& outcome);

// Relaxation's first stage: from `settling` (at the positions to start from; velocities set to
// zero), steps of dt with the forces `quiet` leaves on, supports held still, overdamped by
// model.settle.damping (automatic_settle_damping when empty; 0 skips the stage), until every free
// node carries 90 % of its weight (or model.settle.residual, if that is looser) or
// model.settle.duration has passed. Positions, velocities and histories are left in `settling`,
// the static forces there in settling.force; the outcome counts the steps.
SettleOutcome creep_under_gravity(const Model& model, double dt, const ForceSwitches& quiet,
                                  State& settling);

// Both stages: the creep, then kinetic damping until the out-of-balance force is at most
// model.settle.residual of every node's weight, `stop` ends it at a restart, or
// model.settle.duration has passed. Positions and
// histories are left in `settling`; the outcome is returned (converged when its residual is at
// most model.settle.residual).
SettleOutcome relax_to_rest(const Model& model, double dt, const ForceSwitches& quiet,
                            State& settling, const RestartTest& stop = {});

}  // namespace dinam
