#pragma once
// Ties (`attach`, model.hpp's Ties): each holds a node x at its start offset o from a point of
// another object, p = Σ w_k x_k over up to three of its nodes, by a spring of stiffness k on
// d = x − p − o (energy ½ k |d|², its force on the point's nodes shared by their weights), so that
// a rope's end follows its hook, a flag's ties their pole, a collar its shoulder; a tie that
// swings keeps its start distance L alone (o = 0, energy ½ k (|d| − L)²), free to turn around the
// point, as a loop on a pole does. Under `integrator: xpbd` they are held as constraints with the
// bars: C = |d| − L of compliance 1/k, 0 for a rigid tie. A tie that pulls harder than its
// break_force breaks for good at the start of a step, serially in tie order (the same for any
// thread count).
#include "dynamics/force_kind.hpp"

namespace dinam {

struct Model;
struct State;

// The tie's tension at the state's positions, N (≥ 0 in tension, < 0 pushed): k (|d| − L), or
// under `integrator: xpbd` what its last projection held (the spring's before the first).
double tie_tension(const Model& model, const State& state, Index tie);

// Breaks every tie whose tension's magnitude exceeds its break_force; the energy it held is booked
// as dissipated, as a torn bar's is (dynamics/tearing.hpp).
void break_overloaded_ties(const Model& model, State& state);

extern const ForceKind kTies;

}  // namespace dinam
