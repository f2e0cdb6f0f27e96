#pragma once
// What a step of the implicit integrator costs, estimated from what the model holds and from the
// size of its Hessian's Cholesky factor (CHOLMOD's analysis of the pattern, no numbers), so that
// `info` can set the two integrators side by side the same way on a quiet machine and a busy one
// (docs/threads.md, "The estimate of a run"). The per-item costs are bench_implicit --costs's on
// the machine of docs/performance.md; how many Newton iterations and factorisations a step takes
// depends on the motion (a swing takes a few, an impact on the ground tens), and the estimate
// assumes the middle of what bench_implicit measured.
#include "dynamics/step_cost.hpp"

namespace dinam {

struct Model;

// Newton iterations, iterations of their linear solves (conjugate gradients) and factorisations
// a step is assumed to take, the middle of what bench_implicit measured over the scenes of
// docs/implicit-integrator.md: a free fall 1, 1 and 0.03; a steel cable swinging 5.4, 56 and 0.85; the
// paper's flag 5.0, 52 and 0.27; the Wuson over its 3 s (landing, folding, at rest) 9.8, 132 and
// 1.25 without the ground's restitution, 15.1, 197 and 2.25 with it, bouncing (so its estimate is
// a third of what it takes).
inline constexpr double kAssumedIterationsPerStep = 6.0;
inline constexpr double kAssumedSolveIterationsPerStep = 60.0;
inline constexpr double kAssumedFactorizationsPerStep = 1.0;
// And those of a step that contact between objects' speed envelope split off (a few
// milliseconds): the paper's ball in the trampoline's net, 5 844 such steps over 4 s, took 2.3,
// 16 and 0.01.
inline constexpr double kShortStepIterations = 2.3;
inline constexpr double kShortStepSolveIterations = 16.0;
inline constexpr double kShortStepFactorizations = 0.01;

struct HessianFactorSize {
  double unknowns = 0.0;  // free degrees of freedom
  double nonzeros = 0.0;  // in L
  double flops = 0.0;     // of one factorisation
};

// The Cholesky factor of the model's stiffness pattern (every spring's blocks, the free nodes'
// diagonal blocks), fill-reducing ordered as CHOLMOD orders it.
HessianFactorSize hessian_factor_size(const Model& model);

struct ImplicitStepCost {
  HessianFactorSize factor;
  double factorization_seconds = 0.0;    // assembling the Hessian and factorising it, once
  double iteration_seconds = 0.0;        // a Newton iteration: forces and energies
  double solve_iteration_seconds = 0.0;  // one of its solve's: a solve with the factor, a force
  double seconds = 0.0;                  // a step at the assumed iterations and factorisations
  double short_step_seconds = 0.0;       // a step split off by contact's speed envelope
};

// `forces`: the cost of one evaluation of the model's forces (central differences' step cost,
// dynamics/step_cost.hpp), on one thread.
ImplicitStepCost estimate_implicit_step(const Model& model, const StepCost& forces);

}  // namespace dinam
