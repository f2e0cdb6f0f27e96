#pragma once
// How one implicit step's problem (step_problem.hpp) is minimised over its scheme
// (step_scheme.hpp): Newton's method in a trust region (implicit_newton.hpp), the Hessian of the
// incremental potential assembled from every force kind's element matrices and factorised, the
// factorisation kept over iterations and steps; or quasi-Newton about projective dynamics'
// constant matrix (quasi_newton.hpp), where the integrator's options ask.
#include <Eigen/SparseCore>
#include <vector>

#include "dynamics/free_dofs.hpp"
#include "solver/constant_system.hpp"
#include "solver/implicit_integrator.hpp"
#include "solver/implicit_newton.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/quasi_newton.hpp"
#include "solver/stiffness_matrix.hpp"
#include "solver/triplet_matrix.hpp"

namespace dinam {

struct Model;
struct State;
struct StepProblem;
struct StepScheme;

class StepMinimiser {
 public:
  explicit StepMinimiser(ImplicitMinimiser method) : method_(method) {}

  // Minimises `problem` over the free nodes of state.x from where it places the start, for a step
  // of `scheme` on a model of median bar `bar`; false (state.x anywhere) where it did not
  // converge. Its iterations are added to `stats`.
  bool minimise(const Model& model, State& state, StepProblem& problem, const StepScheme& scheme,
                double bar, ImplicitStats& stats);

 private:
  // Assembles and factorises the incremental potential's Hessian at state.x for a step of `hs`:
  // the stiffness as it is, which M/h² makes definite unless a step is long against a buckling
  // structure's instability; else with each element's matrix made definite (a descent still, if
  // slower).
  bool factor(const Model& model, State& state, StepProblem& problem, double hs);
  bool newton(const Model& model, State& state, StepProblem& problem, const StepScheme& scheme,
              double bar, ImplicitStats& stats);
  bool quasi_newton(const Model& model, State& state, StepProblem& problem,
                    const StepScheme& scheme, double bar, ImplicitStats& stats);

  ImplicitMinimiser method_;
  // Newton's: the Hessian factorised last (of a step of `factored_h_`, where `factored_`), the
  // friction springs' and contact's share of it, and the trust region, carried from step to step.
  StiffnessAssembly assembly_;
  PositiveDefiniteSolver solver_{kFastestSupernodalFrom};
  DofTriplets contact_triplets_;
  TripletMatrix held_;
  SparseMatrix system_;
  bool factored_ = false;
  double factored_h_ = 0.0;
  double trust_radius_ = 0.0;
  NewtonWorkspace newton_;
  // Quasi-Newton's: the constant matrix, factorised for a step of `constant_h_`.
  ConstantSystem constant_;
  double constant_h_ = 0.0;
  QuasiNewtonWorkspace quasi_;
};

}  // namespace dinam
