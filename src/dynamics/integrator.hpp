#pragma once
// Central differences in leapfrog form (DESIGN.md):
//   a_n = M⁻¹ F(x_n, v_{n−½}, t_n),  v_{n+½} = v_{n−½} + Δt a_n,  x_{n+1} = x_n + Δt v_{n+½}.
// Velocity-dependent forces (dampers, friction, drag) use v_{n−½}, the latest velocity known
// before the step; the stability bound accounts for the lag.
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Which force kinds act; each can be switched off so that a test isolates one.
struct ForceSwitches {
  bool gravity = true;
  bool fields = true;
  bool axial_springs = true;
  bool axial_dampers = true;
  bool bending = true;
  bool torsion = true;
  bool global_damping = true;
  bool wind = true;
  bool ground = true;
  bool object_contact = true;  // between objects and within one
};

// The state at t = 0: x_0 and v_0 from the model, and v_{−½} = v_0 − ½Δt a_0 so that the first
// half-step velocity is v_{½} = v_0 + ½Δt a_0. With `track_energy`, every step also keeps the
// energy accounts and report (at some cost).
State initial_state(const Model& model, double dt, const ForceSwitches& switches = {},
                    bool track_energy = false);

// Computes the total force on every node at (x_n, v_{n−½}, t_n) into state.force. With
// update_history false, plastic sets and contact anchors are left as they are.
void compute_forces(const Model& model, const ForceSwitches& switches, State& state,
                    bool update_history = false);

// Advances the state by one step of dt. Allocates nothing. Throws RuntimeError naming the node,
// the step and the time if a position or velocity stops being finite.
void step(const Model& model, double dt, const ForceSwitches& switches, State& state);

}  // namespace dinam
