#pragma once
// What a step of a model costs, estimated from what it holds (springs of each kind, nodes, faces
// in the wind, contact primitives: each force kind counts its own items into the sink,
// step_cost_sink.hpp) and a cost per item, measured once by the benchmark (bench/force_costs.cpp,
// one thread) and kept in measured_costs.hpp. The estimate does not depend on
// how busy the machine is now, so the same scene gets the same answer on a quiet machine and on
// a shared one (a test or a refusal can rest on it); it is the time on a machine like the one the
// costs were measured on (bench/notes/performance.md), which a faster or slower machine scales.
#include "estimate/step_cost_sink.hpp"

namespace dinam {

struct Model;

// The cost of a step of `model` on `threads` threads. The spring, node and drag loops are split
// between the threads where the model is large enough for that to pay (the step's own rule), at
// the efficiency bench_threads measures on two idle cores; contact between objects is counted at
// the cost of watching for it, a surface with contact with itself (a cloth that folds) at what a
// cloth lying on itself costs.
// With `as_xpbd`, the step of `integrator: xpbd` whatever the model's own integrator: the kinds it
// holds as constraints cost their projection's sweeps, on one thread, not their forces.
StepCost estimate_step_cost(const Model& model, int threads, bool as_xpbd = false);

}  // namespace dinam
