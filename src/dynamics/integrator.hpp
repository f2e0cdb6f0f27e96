#pragma once
// Central differences in leapfrog form (docs/architecture.md, "Integration"):
//   a_n = M⁻¹ F(x_n, v_{n−½}, t_n),  v_{n+½} = v_{n−½} + Δt a_n,  x_{n+1} = x_n + Δt v_{n+½}.
// Velocity-dependent forces (dampers, friction, drag) use v_{n−½}, the latest velocity known
// before the step; the stability bound accounts for the lag.
#include <cstdint>

#include "dynamics/force_switches.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Every array of the state for `model` allocated in this one place (state_arrays.hpp lists them),
// at x_0 and v_0 from the model (driven pins where their paths start); the energy ledger's arrays
// only with `track_energy`. Computes no force: start_leapfrog does (initial_state in
// stepping/time_step.hpp makes the state at t = 0, settled as the scene asks).
State make_state(const Model& model, bool track_energy);

// The forces a step of `model` finds, of those `switches` leaves on: where the bars are
// constraints (`integrator: xpbd`, bar_constraints.hpp), all but their axial springs and dampers,
// which the step's projection holds instead.
ForceSwitches stepped_switches(const Model& model, ForceSwitches switches);

// Starts leapfrog from rest or from v_0 at the state's positions: the forces at (x_0, v_0) into
// state.force, then v_{−½} = v_0 − ½Δt a_0.
void start_leapfrog(const Model& model, double dt, const ForceSwitches& switches, State& state);

// Computes the total force on every node at (x_n, v_{n−½}, t_n) into state.force. With
// update_history false, plastic sets and contact anchors are left as they are.
void compute_forces(const Model& model, const ForceSwitches& switches, State& state,
                    bool update_history = false);

// The forces as compute_forces gives them, but taken at `time` instead of the state's (the fields
// and the wind read it): the implicit step's loads at the step's end, the state's clock unmoved.
// Plastic sets and contact anchors are left as they are.
void compute_forces_at(const Model& model, const ForceSwitches& switches, State& state,
                       double time);

// The static forces at the present positions into state.force: velocities set to zero (no damping
// or drag), plastic sets and contact anchors left as they are.
void compute_static_forces(const Model& model, const ForceSwitches& switches, State& state);

// The forces of the potential alone at the present positions into state.force, −∇V of the kinds
// `switches` leaves on (potential kinds: springs, gravity and fields, the ground's penalty), the
// plastic sets held: neither the velocities nor the contact history are read, nor anything of the
// state but state.force written. Newton's gradient in the implicit step.
void compute_potential_forces(const Model& model, const ForceSwitches& switches, State& state);

// Whether a step of `model` has enough work to pay for sharing it between threads
// (kMinParallelItems springs), and whether it does: where the process's team (core/
// thread_team.hpp) has several threads.
bool worth_sharing(const Model& model);
bool step_runs_in_parallel(const Model& model);

// How the team shares the work on `state` (work_split.hpp), made for the team's size when it is
// not yet; null when a step of the model runs on one thread.
const WorkSplit* share_work(const Model& model, State& state);

// Advances the state by `steps` steps of dt, bit for bit as that many calls of step() would, in
// one job of the thread team (core/thread_team.hpp), whose threads then meet once a step instead
// of being woken and gathered for each. Throws as step() does, at the step that diverged.
void advance_steps(const Model& model, double dt, const ForceSwitches& switches, State& state,
                   std::int64_t steps, const StepOptions& options = {});

// Advances the state by one step of dt. Allocates nothing. Throws RuntimeError naming the node,
// the step and the time if a position or velocity stops being finite.
void step(const Model& model, double dt, const ForceSwitches& switches, State& state,
          const StepOptions& options = {});

}  // namespace dinam
