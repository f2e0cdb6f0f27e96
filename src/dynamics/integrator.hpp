#pragma once
// Central differences in leapfrog form (DESIGN.md):
//   a_n = M⁻¹ F(x_n, t_n),  v_{n+½} = v_{n−½} + Δt a_n,  x_{n+1} = x_n + Δt v_{n+½}.
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Which force kinds act; each can be switched off so that a test isolates one.
struct ForceSwitches {
  bool gravity = true;
  bool axial_springs = true;
};

// The state at t = 0: x_0 and v_0 from the model, and v_{−½} = v_0 − ½Δt a_0 so that the first
// half-step velocity is v_{½} = v_0 + ½Δt a_0.
State initial_state(const Model& model, double dt, const ForceSwitches& switches = {});

// Computes the total force on every node at (x_n, t_n) into state.force.
void compute_forces(const Model& model, const ForceSwitches& switches, State& state);

// Advances the state by one step of dt. Allocates nothing. Throws RuntimeError naming the node,
// the step and the time if a position or velocity stops being finite.
void step(const Model& model, double dt, const ForceSwitches& switches, State& state);

}  // namespace dinam
