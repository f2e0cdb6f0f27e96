#pragma once
// The settling phase before t = 0 (SettlePhase): the structure hangs or rests under gravity alone
// until it is in static equilibrium, and the shape it reaches becomes the start of the shown
// motion. Fields, wind, initial velocities and moving supports wait until t = 0.
//
// By default the equilibrium is found by Newton's method on the potential energy (equilibrium.hpp):
// a static problem, solved in a few iterations whatever the masses and the step. Dynamic
// relaxation (dynamics/relaxation.hpp) serves instead where the scene asks for it (`method:
// relax`) and, with a note saying why, where the equilibrium depends on the way the structure came
// to it, which a static solve does not know:
//  - contact between objects (where a draped body rests is decided by how it slid there);
//  - ground that slopes under gravity (friction holds what rests on it);
//  - a spring that would yield, or a bar that would tear, at the equilibrium Newton found (the
//    plastic set depends on the path);
//  - Newton's method failing to converge (a mechanism: a part free to move without resisting).
#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// Runs the phase from `state` (at the mesh positions, at rest), leaving the positions and
// histories reached in `state` and the outcome in state.settled; relaxation steps by dt. Does
// nothing without a phase. Throws UserError at the scene's `settle` when it has not converged.
void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state);

}  // namespace dinam
