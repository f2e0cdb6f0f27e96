#include "solver/implicit_cost.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "model/disjoint_sets.hpp"
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

// Below this share of its motions left free by its bars, a structure holds its shape.
constexpr double kHeldShapeShare = 0.02;

// The pieces of the mesh that its bars join: each node's piece (named by a node of it), and by
// piece, how many nodes and whether a pin holds it.
struct MeshPieces {
  std::vector<Index> piece;        // (n_nodes)
  std::vector<int> size;           // (n_nodes) by piece
  std::vector<std::uint8_t> held;  // (n_nodes) by piece
};

MeshPieces mesh_pieces(const Model& model) {
  const auto n = static_cast<std::size_t>(model.node_count());
  DisjointSets sets(n);
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index root_i = sets.find(model.bar_nodes[2 * b]);
    const Index root_j = sets.find(model.bar_nodes[2 * b + 1]);
    if (root_i != root_j) {
      sets.join(root_i, root_j);
    }
  }
  MeshPieces pieces{sets.roots(), std::vector<int>(n, 0), std::vector<std::uint8_t>(n, 0)};
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index piece = pieces.piece[i];
    pieces.size[piece] += 1;
    pieces.held[piece] = pieces.held[piece] != 0 || model.pinned(i) ? 1 : 0;
  }
  return pieces;
}

double bars_free_share(const Model& model, const MeshPieces& pieces) {
  const auto n = static_cast<std::size_t>(model.node_count());
  // By piece: its free motions less its rigid ones (6, 3 for a lone node, none where a pin holds
  // it), less its bars with a free node; each piece's count at least 0, so that bars one piece
  // repeats do not hide another's free motions.
  std::vector<double> left(n, 0.0);
  double free_motions = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double motions = model.pinned(i) ? 0.0 : 3.0;
    left[pieces.piece[i]] += motions;
    free_motions += motions;
    if (pieces.piece[i] == i && pieces.held[i] == 0) {
      left[i] -= pieces.size[i] == 1 ? 3.0 : 6.0;
    }
  }
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index i = model.bar_nodes[2 * b];
    const Index j = model.bar_nodes[2 * b + 1];
    if (!model.pinned(i) || !model.pinned(j)) {
      left[pieces.piece[i]] -= 1.0;
    }
  }
  double free_share = 0.0;
  for (const double motions : left) {
    free_share += std::max(motions, 0.0);
  }
  return free_motions > 0.0 ? free_share / free_motions : 0.0;
}

}  // namespace

double bars_free_share(const Model& model) {
  return bars_free_share(model, mesh_pieces(model));
}

ImplicitMotion expected_motion(const Model& model) {
  const MeshPieces pieces = mesh_pieces(model);
  if (bars_free_share(model, pieces) < kHeldShapeShare) {
    return ImplicitMotion::kHoldsItsShape;
  }
  const bool free_piece = std::any_of(pieces.piece.begin(), pieces.piece.end(),
                                      [&](Index piece) { return pieces.held[piece] == 0; });
  const bool something_to_land_on = model.ground.enabled || model.contact.enabled;
  return free_piece && something_to_land_on ? ImplicitMotion::kFolds : ImplicitMotion::kSwings;
}

ImplicitStepCounts assumed_step_counts(ImplicitMotion motion) {
  switch (motion) {
    case ImplicitMotion::kHoldsItsShape:
      return {4.0, 35.0, 0.1};
    case ImplicitMotion::kFolds:
      return {14.0, 140.0, 1.0};
    case ImplicitMotion::kSwings:
      break;
  }
  return {5.5, 55.0, 0.5};
}

const char* motion_text(ImplicitMotion motion) {
  switch (motion) {
    case ImplicitMotion::kHoldsItsShape:
      return "its bars hold its shape";
    case ImplicitMotion::kFolds:
      return "its bars leave some of its motions to the bending and torsion springs, and it "
             "lands: it folds";
    case ImplicitMotion::kSwings:
      break;
  }
  return "held by its pins or with nothing to land on: it swings";
}

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
  cost.motion = expected_motion(model);
  cost.counts = assumed_step_counts(cost.motion);
  cost.seconds = cost.counts.iterations * cost.iteration_seconds +
                 cost.counts.solve_iterations * cost.solve_iteration_seconds +
                 cost.counts.factorizations * cost.factorization_seconds;
  cost.short_step_seconds = kShortStepIterations * cost.iteration_seconds +
                            kShortStepSolveIterations * cost.solve_iteration_seconds +
                            kShortStepFactorizations * cost.factorization_seconds;
  return cost;
}

}  // namespace dinam
