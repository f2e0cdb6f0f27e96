#pragma once
// The minimisation of one implicit step's incremental potential E (implicit_integrator.hpp) by
// Newton's method in a trust region, from wherever the integrator put state.x (the prediction
// x̂): each Newton step is Steihaug's truncated conjugate gradients (truncated_cg.hpp) on the
// Hessian's products, taken from differences of the gradient and preconditioned with a
// factorised Hessian P kept over iterations and steps, within a region |s|_P ≤ Δ in P's norm; a
// step is taken where E falls by enough of what the quadratic model promised, and Δ grows or
// shrinks with how well they agreed. A structure that buckles has directions of negative
// curvature, which the region lets a step follow as far as the model holds, and a folding
// structure's energy is far from quadratic over a bar's length: the region keeps the solves
// from computing Newton steps that a line search would then cut to a fraction (docs/
// implicit-integrator.md, "A trust region"). The integrator defines E for the step (its gradient,
// its value, the Hessian's factorisation, the friction of nodes that land); this file holds how a
// minimum is found and when it is found.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/function_ref.hpp"
#include "core/types.hpp"
#include "solver/truncated_cg.hpp"

namespace dinam {

struct FreeDofs;

// A step is found once a Newton step has been taken and either the out-of-balance force left
// would move no node by more than this share of the median bar within the step (|g_i| h²/m_i), or
// a whole Newton step moved none by more: far below what can be seen, far above rounding. (The
// second test is the one a node pressed on the ground meets: the ground's stiffness, not its
// mass, sets how far its residual force moves it.) Neither share may stand for an out-of-balance
// acceleration above kConvergedAcceleration: the error each step leaves is a velocity error of
// |g|h/m, and the motion's over a second is their sum, so on short steps (a pendulum of one
// 1 m bar at 2.5 ms steps allowed 1.6 m/s² and lost half its swing in two periods) the bar's
// share would allow too much. (1e-3 of g: over 3 s at most 3 cm/s of drift; the pendulum then
// keeps its swing to 0.5 mm at 2.5 ms. 1e-4 of g made the Wuson's first 0.5 s take a third
// longer, for no difference to be seen.)
inline constexpr double kConvergedShare = 1e-5;
inline constexpr double kConvergedAcceleration = 1e-2;  // m/s²

// One step's incremental potential, as the integrator defines it for the step. Each function
// works at state.x, the iterate. Referred to, not kept: each must outlive the minimisation.
struct StepPotential {
  FunctionRef<void(Eigen::VectorXd& g)> gradient;  // ∇E, over the free degrees of freedom
  FunctionRef<double()> energy;                    // E
  // Assembles and factorises the Hessian here into the kept factorisation; false where even its
  // definite projection is not positive definite.
  FunctionRef<bool()> factor;
  // The kept factorisation's solve, P⁻¹ r.
  FunctionRef<void(const Eigen::VectorXd& r, Eigen::VectorXd& solved)> precondition;
  // Nodes that went below the ground at this iterate since the step's start join its friction
  // (ImplicitFriction::join_new_touches): true where E has changed with them.
  FunctionRef<bool()> join_new_touches;
  // At what would be the step's solution: true where nodes that landed within the step join its
  // friction (ImplicitFriction::add_new_touches), so that the step must be solved on.
  FunctionRef<bool()> add_new_touches;
};

// What a minimisation works in, kept by the caller from step to step so that once its arrays
// have their sizes a step allocates nothing.
struct NewtonWorkspace {
  Eigen::VectorXd g, g_moved;   // the gradient at the iterate, and at the iterate moved
  std::vector<Vec3> x_iterate;  // the iterate, while the Hessian's product moves it
  std::vector<Vec3> from;       // the iterate, while a step from it is tried
  TruncatedCg path;             // the Newton step's
  TruncatedCg::Point point;     // the step tried
};

// What a minimisation did, to be added to the run's counts (ImplicitStats).
struct NewtonCounts {
  std::int64_t iterations = 0;        // Newton iterations
  std::int64_t solve_iterations = 0;  // of their conjugate gradients
  std::int64_t factorizations = 0;    // Hessians assembled and factorised
};

// Minimises `potential` over the free nodes of state.x (dofs), starting from state.x, for a step
// of `h` (the one the minimisation takes: BDF2's 2h/3) on a model of these free masses (one per
// degree of freedom) and median bar. `factored` says whether the kept factorisation may be used
// (the caller clears it where h changed); it is cleared where the kept one stopped describing
// the Hessian. `radius` is the trust region's, in the kept factorisation's norm, carried from
// step to step (the caller sets it to 0, "none yet", where h changed). True with state.x at the
// minimum; false where Newton's method found no step (the caller splits the step).
bool minimise_step(std::vector<Vec3>& x, const FreeDofs& dofs, const Eigen::VectorXd& mass,
                   double h, double bar, const StepPotential& potential, bool& factored,
                   double& radius, NewtonCounts& counts, NewtonWorkspace& work);

}  // namespace dinam
