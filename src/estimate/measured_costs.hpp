#pragma once
// Every measured figure the run-time estimates rest on, in one table: nanoseconds per item on one
// thread of the machine of bench/notes/performance.md. Each force kind counts the items it loops
// over (dynamics/force_kind.hpp's add_cost) and multiplies by its figure here; estimate_step_cost
// (step_cost.hpp) and estimate_implicit_step (implicit_cost.hpp) sum them. Nothing but the
// estimates that `info` prints, and that `render` and `simulate` refuse over-long runs on, reads
// them. When a kernel changes, measure again with the benchmark named beside its figure and
// update it here; `python3 bench/estimate_check.py build/dinam` then compares every estimate with
// a run.
//
// Header-only and without dependencies, so that the force kinds below the estimates can read it.

namespace dinam::measured {

// --- Central differences' step: `build/bench/bench_force_costs` (bench/force_costs.cpp), the
// large flag and its lattice, about 100 000 of each kind (bench/notes/performance.md, "Every force
// kind against the springs"). Springs: elastic, and of a kind that can yield.
inline constexpr double kNsPerAxialSpring = 5.5;
inline constexpr double kNsPerAxialSpringYielding = 6.6;
inline constexpr double kNsPerBendingSpring = 14.5;
inline constexpr double kNsPerBendingSpringYielding = 18.2;
inline constexpr double kNsPerClampSpring = 20.0;  // serial: one loop in clamp order
inline constexpr double kNsPerClampSpringYielding = 20.0;
inline constexpr double kNsPerTorsionSpring = 23.2;
inline constexpr double kNsPerTorsionSpringYielding = 25.0;
inline constexpr double kNsPerDamper = 5.3;  // a bar's axial damper
// Gravity, clearing and the integrator, per node; a bar checked against its breaking limit.
inline constexpr double kNsPerNode = 5.4;
inline constexpr double kNsPerTearingBar = 1.0;
inline constexpr double kNsPerFieldNode = 0.8;   // a node a field acts on
inline constexpr double kNsPerDampedNode = 1.3;  // global damping, per node
inline constexpr double kNsPerGroundNode = 9.2;  // half of them touching
inline constexpr double kNsPerWindFace = 15.1;
inline constexpr double kNsPerWindFaceTurbulent = 25.3;
inline constexpr double kNsPerWindBar = 10.1;  // a bare bar in the wind
inline constexpr double kNsPerWindBarTurbulent = 17.6;
// A tie's forces, serial: each thread takes every tie, adding to its own nodes.
inline constexpr double kNsPerTie = 15.0;
// A bar or node watched for contact between objects.
inline constexpr double kNsPerWatched = 30.0;
// A bar or node of a surface in contact with itself: a cloth that folds lies on itself or on what
// it lands on for most of a run, where its searches and candidates cost far more than watching.
// bench_contact's two sheets lying on each other (130 000 bars and nodes, one thread): 42.5 ms a
// step against 6.1 ms without contact. The paper's draped cloth, counted at watching's cost, ran
// eleven times its estimate. Its searches are not shortened by a second thread at that size (8.7 s
// on one thread and on two).
inline constexpr double kNsPerPressed = 280.0;

// A step on two idle threads against one, as bench_threads measures on 5 000 to 50 000 bars:
// each thread past the first adds this fraction of one.
inline constexpr double kThreadEfficiency = 0.8;

// --- `integrator: xpbd`: one bar's (or tie's) projection in a sweep, the windy flag's 3 434
// bars, four sweeps a step, in its xpbd run (bench/notes/stiff-threads.md).
inline constexpr double kNsPerBarProjection = 6.0;

// --- The implicit integrator: `bench_implicit --costs` (bench/implicit_benchmark.cpp) on the
// Wuson, the paper's flag and the end-to-end flag, one thread, with CHOLMOD's supernodal factor
// through the single-threaded OpenBLAS (solver/positive_definite_solver.hpp):
// - a factorisation 0.27, 0.34 and 0.65 ns a flop of CHOLMOD's count (the larger the model, the
//   larger its dense blocks and the less a flop costs);
// - an assembly 0.9 to 1.3 µs a spring with the exact Hessians, 2.7 to 5.2 µs with each
//   element's projected; a factorisation whose exact Hessian is indefinite takes both, so about
//   3 µs is taken;
// - a solve 0.35, 0.47 and 0.61 ns a nonzero of the factor, forward and back each;
// - a Newton iteration evaluates the forces once and the energy once or twice (the line
//   search), each about a step of central differences' forces: 3 in all; each iteration of its
//   linear solve, a solve with the factor and one force evaluation (the Hessian's product);
// - a solve with a small factor costs more than its nonzeros: 6.2 and 8.7 µs for factors of 1 701
//   and 2 373 nonzeros (the paper's rope and a steel cable), where 0.4 ns a nonzero each way
//   predicts 1.4 and 1.9 µs: a call's own cost, about 5 µs, which a large factor hides.
inline constexpr double kNsPerFlop = 0.3;
inline constexpr double kAssemblyNsPerSpring = 3000.0;
inline constexpr double kForceEvaluationsPerIteration = 3.0;
inline constexpr double kNsPerFactorNonzero = 0.4;
inline constexpr double kNsPerSolveCall = 5000.0;

}  // namespace dinam::measured
