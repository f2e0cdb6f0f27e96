#pragma once
// What a step of the implicit integrator costs, estimated from what the model holds and from the
// size of its Hessian's Cholesky factor (CHOLMOD's analysis of the pattern, no numbers), so that
// `info` can set the two integrators side by side the same way on a quiet machine and a busy one
// (bench/notes/threads.md, "The estimate of a run"). The per-item costs are bench_implicit
// --costs's on the machine of bench/notes/performance.md; how many Newton iterations and
// factorisations a step takes depends on the motion (a swing takes a few, a structure that folds
// where it lands tens), and the estimate assumes what bench_implicit measured for models that move
// alike.
#include <string>

#include "core/types.hpp"
#include "estimate/step_cost.hpp"

namespace dinam {

struct Model;

// Newton iterations, iterations of their linear solves (conjugate gradients) and factorisations
// a step takes.
struct ImplicitStepCounts {
  double iterations = 0.0;
  double solve_iterations = 0.0;
  double factorizations = 0.0;
};

// How the model's motion is expected to go, which sets the counts a step is assumed to take. They
// differ by ten times in factorisations a step between models of the same size, material and
// drop (bench/notes/implicit-integrator.md, "Which integrator"), and what sets them is whether the
// bars alone hold the structure's shape:
enum class ImplicitMotion {
  // Its bars leave under 2 % of its motions free (a triangulated closed surface leaves none):
  // it keeps its shape where it lands, and comes to rest there; the Hessian changes little from
  // step to step. Measured: NFF's spheres.nff 3.5 Newton iterations, 30 solve iterations and
  // 0.11 factorisations a step, WithCamera.nff 4.2, 40 and 0.13, COLLADA.dae 2.9 Newton
  // iterations.
  kHoldsItsShape,
  // Its bars hold its shape, but a free piece of it lands off balance on a round base
  // (landing_balance.hpp): it rocks, rolls or topples, and goes on moving on the ground, where
  // the nodes that touch it change from step to step and with them the Hessian. Measured:
  // fromtruespace_bin32.x 3.1, 30 and 0.025; assimp's collada.ogex, whose letters land standing
  // and whose C, o and d rock and roll on their round backs for seconds, 5.2, 58 and 0.27;
  // MotionCaptureROM.ase's 26 shells 8.6, 85 and 0.75. Assumed: the middle one.
  kRocks,
  // More of its motions are held only by the bending and torsion springs, and a piece of it is
  // free with the ground or contact between objects to land on: it folds under its own weight
  // where it lands, nearly a static problem of a buckling shell at each step. Measured: the
  // Wuson 12.3, 114 and 0.94; issue_2229.dxf 13, 108 and 0.7; MotionCaptureROM.ase 15.5, 144 and
  // 1.13; HUMAN.blend's first second 19, 190 and 1.18.
  // The counts above are of the Wuson's first half second; once it lies folded on the ground its
  // steps take far more (the whole 3 s ran over 300 s against 19 s estimated), and no count
  // measured on one folding model has held for another: the estimate is not to be trusted.
  kFolds,
  // A piece that no pin holds and that its bars do not hold in shape, with nothing to land on:
  // it tumbles, turning through large angles a step, where Newton's method takes more iterations
  // the faster it turns. Not measured; assumed as a fold, and not trusted either.
  kTumbles,
  // Held by its pins: it swings. Measured (BDF2 where the scene asks for it): the paper's flag
  // 5.0, 52 and 0.27; a steel cable 5.0, 51 and 0.84; the paper's rope swinging onto the ground
  // 6.2, 71 and 0.79. Assumed: about the largest of each, as a swing onto the ground takes.
  kSwings,
};

// How many times short the implicit estimate of a structure that moves so may be: 1 where it
// swings (held by its pins, its estimates measured within a factor of two); 10 for a free
// structure, which lands or tumbles, where runs of the real-mesh sweep took up to ten times and
// more their estimate (E-AT-AT.q3o folding, over 10; MotionCaptureROM.ase's 26 tumbling shells,
// 10 at the counts of a structure that lies still, 3.2 at a rocking one's;
// bench/notes/implicit-integrator.md). The recommendation (estimate/integrator_choice.hpp)
// weighs the estimate by it.
double estimate_margin(ImplicitMotion motion);

// The share of the model's free motions that its bars leave free: Maxwell's count of a bar
// framework, 3 n − b − 6 for each piece of the mesh with n free nodes and b bars with a free node
// (the 6 its rigid motions, only where no pin holds the piece), at least 0, summed over the
// pieces and over 3 n of the whole. A lower bound (a bar may repeat what others hold), and 0
// where the bars alone hold the shape. A piece that lies flat, whose bars hold nothing across
// its plane to first order (a grid's cloth, pinned or not), counts n − 3 across it and
// 2 n − b − 3 in it (without the 3s where a pin holds it).
double bars_free_share(const Model& model);

ImplicitMotion expected_motion(const Model& model);
ImplicitStepCounts assumed_step_counts(ImplicitMotion motion);

struct ImplicitStepCost;
// Why the step takes its counts, in words, for `info` (a piece that lands off balance named by
// its lowest node).
std::string motion_text(const ImplicitStepCost& cost);

// And those of a step that contact between objects' speed envelope split off (a few
// milliseconds): the paper's ball in the trampoline's net, 5 844 such steps over 4 s, took 2.3,
// 16 and 0.01.
inline constexpr double kShortStepIterations = 2.3;
inline constexpr double kShortStepSolveIterations = 16.0;
inline constexpr double kShortStepFactorizations = 0.01;

struct HessianFactorSize {
  double unknowns = 0.0;          // free degrees of freedom
  double nonzeros = 0.0;          // in L
  double flops = 0.0;             // of one factorisation
  double hessian_nonzeros = 0.0;  // in the Hessian itself, both triangles
};

// The Cholesky factor of the model's stiffness pattern (every spring's blocks, the free nodes'
// diagonal blocks), fill-reducing ordered as CHOLMOD orders it: found from the free nodes' graph
// without assembling a value, in memory and time of the order of the springs' count.
HessianFactorSize hessian_factor_size(const Model& model);

struct ImplicitStepCost {
  HessianFactorSize factor;
  ImplicitMotion motion = ImplicitMotion::kSwings;
  Index off_balance_node = -1;           // kRocks: the lowest node of the piece that tips first
  ImplicitStepCounts counts;             // a step's, as `motion` assumes
  double factorization_seconds = 0.0;    // assembling the Hessian and factorising it, once
  double iteration_seconds = 0.0;        // a Newton iteration: forces and energies
  double solve_iteration_seconds = 0.0;  // one of its solve's: a solve with the factor, a force
  double seconds = 0.0;                  // a step at `counts`
  double short_step_seconds = 0.0;       // a step split off by contact's speed envelope
};

// `forces`: the cost of one evaluation of the model's forces (central differences' step cost,
// estimate/step_cost.hpp), on one thread.
ImplicitStepCost estimate_implicit_step(const Model& model, const StepCost& forces);

}  // namespace dinam
