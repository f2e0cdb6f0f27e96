#include "solver/implicit_cost.hpp"

#include <Eigen/CholmodSupport>

#include "model/model.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {

namespace {

// Measured by `bench_implicit --costs` (bench/implicit_benchmark.cpp) on the Wuson, the paper's
// flag and the end-to-end flag, one thread, 2026-11-26, with CHOLMOD's supernodal factor through
// the single-threaded OpenBLAS (positive_definite_solver.hpp):
// - a factorisation 0.27, 0.34 and 0.65 ns a flop of CHOLMOD's count (the larger the model, the
//   larger its dense blocks and the less a flop costs);
// - an assembly 0.9 to 1.3 µs a spring with the exact Hessians, 2.7 to 5.2 µs with each
//   element's projected; a factorisation whose exact Hessian is indefinite takes both, so about
//   3 µs is taken;
// - a solve 0.35, 0.47 and 0.61 ns a nonzero of the factor, forward and back each;
// - a Newton iteration evaluates the forces once and the energy once or twice (the line
//   search), each about a step of central differences' forces: 3 in all; each iteration of its
//   linear solve, a solve with the factor and one force evaluation (the Hessian's product).
constexpr double kNsPerFlop = 0.3;
constexpr double kAssemblyNsPerSpring = 3000.0;
constexpr double kForceEvaluationsPerIteration = 3.0;
constexpr double kNsPerFactorNonzero = 0.4;

}  // namespace

HessianFactorSize hessian_factor_size(const Model& model) {
  const FreeDofs dofs = free_dofs(model);
  HessianFactorSize size;
  size.unknowns = static_cast<double>(dofs.count);
  if (dofs.count == 0) {
    return size;
  }
  const State state = make_state(model, false);
  ForceSwitches springs;
  springs.gravity = springs.fields = springs.wind = false;
  springs.axial_dampers = springs.global_damping = springs.object_contact = false;
  StiffnessAssembly assembly;
  SparseMatrix pattern = assembly.assemble(model, state, springs, dofs, Definiteness::kExact);
  pattern.diagonal().array() += 1.0;  // every diagonal entry present
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> analysis;
  analysis.cholmod().print = 0;
  analysis.analyzePattern(pattern);
  size.nonzeros = analysis.cholmod().lnz;
  size.flops = analysis.cholmod().fl;
  return size;
}

ImplicitStepCost estimate_implicit_step(const Model& model, const StepCost& forces) {
  ImplicitStepCost cost;
  cost.factor = hessian_factor_size(model);
  const auto springs =
      static_cast<double>(model.bar_count() + model.bend_count() + model.torsion_count());
  cost.factorization_seconds =
      1e-9 * (kNsPerFlop * cost.factor.flops + kAssemblyNsPerSpring * springs);
  cost.iteration_seconds = 1e-9 * kForceEvaluationsPerIteration * forces.serial_ns;
  cost.solve_iteration_seconds =
      1e-9 * (forces.serial_ns + 2.0 * kNsPerFactorNonzero * cost.factor.nonzeros);
  cost.seconds = kAssumedIterationsPerStep * cost.iteration_seconds +
                 kAssumedSolveIterationsPerStep * cost.solve_iteration_seconds +
                 kAssumedFactorizationsPerStep * cost.factorization_seconds;
  cost.short_step_seconds = kShortStepIterations * cost.iteration_seconds +
                            kShortStepSolveIterations * cost.solve_iteration_seconds +
                            kShortStepFactorizations * cost.factorization_seconds;
  return cost;
}

}  // namespace dinam
