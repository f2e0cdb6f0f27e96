#include "solver/step_minimiser.hpp"

#include "model/model.hpp"
#include "solver/incremental_potential.hpp"
#include "solver/step_problem.hpp"
#include "solver/step_scheme.hpp"

namespace dinam {

using Vector = Eigen::VectorXd;

bool StepMinimiser::minimise(const Model& model, State& state, StepProblem& problem,
                             const StepScheme& scheme, double bar, ImplicitStats& stats) {
  problem.place_start(state, scheme);
  return method_ == ImplicitMinimiser::kQuasiNewton
             ? quasi_newton(model, state, problem, scheme, bar, stats)
             : newton(model, state, problem, scheme, bar, stats);
}

bool StepMinimiser::factor(const Model& model, State& state, StepProblem& problem, double hs) {
  factored_ = false;
  factored_h_ = hs;
  const FreeDofs& dofs = problem.dofs;
  for (const Definiteness definiteness : {Definiteness::kExact, Definiteness::kProjected}) {
    system_ = assembly_.assemble(model, state, potential_switches(), dofs, definiteness);
    add_sparse(system_, *problem.potential.damping);
    contact_triplets_.clear();
    problem.objects.add_hessian(model, state, dofs, contact_triplets_);
    if (!problem.friction.empty()) {
      problem.friction.add_hessian(dofs, state.x, contact_triplets_);
    }
    if (!contact_triplets_.empty()) {
      add_sparse(system_, held_.set(dofs.count, contact_triplets_));
    }
    system_.diagonal() += problem.potential.inertia;
    if (solver_.factorize(system_)) {
      factored_ = true;
      break;
    }
  }
  return factored_;
}

namespace {

// Runs `minimise` on the StepPotential of `problem` at state.x, with these factorisation and
// solve: the step's gradient, energy and the friction of nodes that land, one set of callbacks
// for either method.
template <class Factor, class Precondition, class Minimise>
bool with_step_potential(const Model& model, State& state, StepProblem& problem,
                         const StepScheme& scheme, Factor& factor, Precondition& precondition,
                         const Minimise& minimise) {
  IncrementalPotential& potential = problem.potential;
  auto gradient = [&](Vector& g) { potential.gradient(g); };
  auto energy = [&] { return potential.energy(); };
  auto join_new_touches = [&] {
    return problem.friction.join_new_touches(model, scheme.x_start, state.x);
  };
  auto add_new_touches = [&] {
    return problem.friction.add_new_touches(model, scheme.x_start, state.x);
  };
  const StepPotential step{
      .gradient = gradient,
      .energy = energy,
      .factor = factor,
      .precondition = precondition,
      .join_new_touches = join_new_touches,
      .add_new_touches = add_new_touches,
  };
  return minimise(step);
}

}  // namespace

bool StepMinimiser::newton(const Model& model, State& state, StepProblem& problem,
                           const StepScheme& scheme, double bar, ImplicitStats& stats) {
  if (factored_h_ != scheme.hs) {  // the kept Hessian, and the region in its norm, are of another h
    factored_ = false;
    trust_radius_ = 0.0;
  }
  auto factor_here = [&] { return factor(model, state, problem, scheme.hs); };
  auto precondition = [&](const Vector& r, Vector& solved) { solver_.solve(r, solved); };
  NewtonCounts counts;
  const bool done = with_step_potential(
      model, state, problem, scheme, factor_here, precondition, [&](const StepPotential& step) {
        return minimise_step(state.x, problem.dofs, problem.mass, scheme.hs, bar, step, factored_,
                             trust_radius_, counts, newton_);
      });
  stats.iterations += counts.iterations;
  stats.solve_iterations += counts.solve_iterations;
  stats.factorizations += counts.factorizations;
  return done;
}

bool StepMinimiser::quasi_newton(const Model& model, State& state, StepProblem& problem,
                                 const StepScheme& scheme, double bar, ImplicitStats& stats) {
  IncrementalPotential& potential = problem.potential;
  if (!constant_.has_springs()) {
    constant_.set_springs(model, state, problem.dofs);
  }
  if (constant_h_ != scheme.hs) {
    if (!constant_.factor(potential.inertia, *potential.damping)) {
      return false;
    }
    constant_h_ = scheme.hs;
    quasi_.forget();
    stats.factorizations += 1;
  }
  auto no_factor = [] { return false; };
  auto precondition = [&](const Vector& r, Vector& solved) { constant_.solve(r, solved); };
  QuasiNewtonCounts counts;
  const bool done = with_step_potential(
      model, state, problem, scheme, no_factor, precondition, [&](const StepPotential& step) {
        return minimise_quasi_newton(state.x, problem.dofs, problem.mass, scheme.hs, bar, step,
                                     counts, quasi_);
      });
  stats.iterations += counts.iterations;
  stats.solve_iterations += counts.energies;
  return done;
}

}  // namespace dinam
