#pragma once
// The solver for stiff threads: one implicit step's incremental potential E (the same as Newton's,
// implicit_integrator.hpp) minimised by the quasi-Newton method of Liu, Bouaziz and Kavan
// ("Quasi-Newton methods for real-time simulation of hyperelastic materials", 2017): L-BFGS whose
// first guess of the inverse Hessian is a constant matrix factorised once (constant_system.hpp:
// projective dynamics' global matrix, the springs' stiffness as no rotation changes it), and a
// backtracking line search on E. Each iteration is one force evaluation, one energy and three
// back-substitutions, where a Newton iteration of the same step assembles and factorises the
// Hessian or builds a conjugate-gradient path of a dozen force evaluations. Cloth and rope stretch
// barely, so the constant matrix is near the Hessian where it matters (the stiff stretch), and
// the few curvature pairs L-BFGS keeps correct it for the turns and folds.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "solver/implicit_newton.hpp"

namespace dinam {

struct FreeDofs;

// What a minimisation works in, kept by the caller from step to step so that once its arrays have
// their sizes a step allocates nothing. Its curvature pairs are the last iterations' (of this
// step or the ones before: the Hessian changes little from step to step).
struct QuasiNewtonWorkspace {
  std::vector<Eigen::VectorXd> s, y;  // the last moves and the gradient's changes over them
  std::vector<double> rho;            // 1 / sᵀy
  int newest = -1;                    // the newest pair's place (a ring)
  int pairs = 0;                      // pairs held
  Eigen::VectorXd g, g_new, direction, q, r;
  std::vector<double> alpha;
  std::vector<Vec3> from;

  // Forgets the curvature pairs (a step of another length, another constant matrix).
  void forget() {
    newest = -1;
    pairs = 0;
  }
};

struct QuasiNewtonCounts {
  std::int64_t iterations = 0;  // force evaluations and solves with the constant matrix
  std::int64_t energies = 0;    // line-search energies
};

// Minimises `potential` over the free nodes of x (dofs), from x, for a step of `h` (the one the
// minimisation takes) on a model of these free masses (one per degree of freedom) and median bar,
// to the same convergence as Newton's method (implicit_newton.hpp); `potential.precondition` is
// the constant matrix's solve, and `potential.factor` is not called. True with x at the minimum;
// false where it was not found in its iterations (the caller splits the step).
bool minimise_quasi_newton(std::vector<Vec3>& x, const FreeDofs& dofs, const Eigen::VectorXd& mass,
                           double h, double bar, const StepPotential& potential,
                           QuasiNewtonCounts& counts, QuasiNewtonWorkspace& work);

}  // namespace dinam
