#pragma once
// The state at t = 0: the model's start, settled under gravity first where the scene asks
// (settle.hpp), and leapfrog started from it.
#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Whether initial_state runs the model's settling phase (settle.hpp), or starts from the mesh
// as it is (to measure a step's cost, say).
enum class Settling { kRun, kSkip };

// The step the settling phase relaxes by (settle.hpp): the run's `dt` under central differences;
// with the implicit integrator, whose steps are far longer than relaxation can take, the automatic
// explicit step instead.
double settling_step(const Model& model, double dt);

// The state at t = 0: x_0 and v_0 from the model (settled first, with kRun, where the model has a
// settling phase), and v_{−½} = v_0 − ½Δt a_0 so that the first half-step velocity is
// v_{½} = v_0 + ½Δt a_0; or, for the implicit integrator, v_0 itself. With `track_energy`, every
// step also keeps the energy accounts and report (at some cost).
State initial_state(const Model& model, double dt, const ForceSwitches& switches = {},
                    bool track_energy = false, Settling settling = Settling::kRun);

}  // namespace dinam
