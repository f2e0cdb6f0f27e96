#include "estimate/implicit_cost.hpp"

#include <cholmod.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "estimate/measured_costs.hpp"
#include "model/mesh_pieces.hpp"
#include "model/model.hpp"
#include "solver/landing_balance.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {

namespace {

// How many times short a free structure's implicit estimate may be (estimate_margin).
constexpr double kFreeStructureMargin = 10.0;

// Below this share of its motions left free by its bars, a structure holds its shape.
constexpr double kHeldShapeShare = 0.02;

// A piece lies flat where its nodes' spread across their plane is below this share of their
// spread along it: a grid is flat to rounding, a mesh read in single precision to 1e-7.
constexpr double kFlatShare = 1e-6;

// Whether the nodes of a piece lie in one plane, to the rounding of a mesh read in single
// precision: the smallest principal spread of their positions against the largest.
bool lies_flat(const Model& model, std::span<const Index> nodes) {
  if (nodes.size() < 3) {
    return false;
  }
  Vec3 mean = Vec3::Zero();
  for (const Index i : nodes) {
    mean += model.node_initial_x[i];
  }
  mean /= static_cast<double>(nodes.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const Index i : nodes) {
    const Vec3 d = model.node_initial_x[i] - mean;
    spread += d * d.transpose();
  }
  const Eigen::Vector3d variances =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(spread, Eigen::EigenvaluesOnly)
          .eigenvalues();  // increasing
  return std::sqrt(std::max(variances[0], 0.0)) <= kFlatShare * std::sqrt(variances[2]);
}

double bars_free_share(const Model& model, const MeshPieces& pieces) {
  // By piece: its free nodes and its bars with a free node.
  const auto n = static_cast<std::size_t>(model.node_count());
  std::vector<double> free_nodes(n, 0.0);
  std::vector<double> bars(n, 0.0);
  for (Index i = 0; i < model.node_count(); ++i) {
    free_nodes[pieces.piece[i]] += model.pinned(i) ? 0.0 : 1.0;
  }
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index i = model.bar_nodes[2 * b];
    const Index j = model.bar_nodes[2 * b + 1];
    if (!model.pinned(i) || !model.pinned(j)) {
      bars[pieces.piece[i]] += 1.0;
    }
  }
  // By piece, the motions its bars leave free: its free motions less its rigid ones (6, 3 for a
  // lone node, none where a pin holds it), less its bars; each piece's count at least 0, so that
  // bars one piece repeats do not hide another's free motions. A piece that lies flat (a grid's
  // cloth) is the exception to Maxwell's count, whose bars all lie in its plane and hold none of
  // its motions across it to first order: its free nodes' motions across the plane (less 3 rigid
  // ones where no pin holds it) and the count in its plane, 2 a free node (less 3) less its bars.
  const std::vector<Index> order = nodes_by_piece(pieces);
  double free_share = 0.0;
  double free_motions = 0.0;
  for (std::size_t first = 0; first < order.size();) {
    const Index piece = pieces.piece[order[first]];
    const auto count = static_cast<std::size_t>(pieces.size[piece]);
    const double f = free_nodes[piece];
    const bool unheld = pieces.held[piece] == 0;
    free_motions += 3.0 * f;
    if (lies_flat(model, std::span<const Index>(order).subspan(first, count))) {
      const double rigid = unheld ? 3.0 : 0.0;
      free_share += std::max(f - rigid, 0.0) + std::max(2.0 * f - rigid - bars[piece], 0.0);
    } else {
      const double rigid = unheld ? (count == 1 ? 3.0 : 6.0) : 0.0;
      free_share += std::max(3.0 * f - rigid - bars[piece], 0.0);
    }
    first += count;
  }
  return free_motions > 0.0 ? free_share / free_motions : 0.0;
}

}  // namespace

double bars_free_share(const Model& model) {
  return bars_free_share(model, mesh_pieces(model));
}

namespace {

// The motion expected, and for a structure that rocks the lowest node of its piece that tips first.
std::pair<ImplicitMotion, Index> expected_motion_and_node(const Model& model) {
  const MeshPieces pieces = mesh_pieces(model);
  if (bars_free_share(model, pieces) < kHeldShapeShare) {
    const std::optional<PieceLanding> rocking = rocking_landing(model, pieces);
    return rocking ? std::pair{ImplicitMotion::kRocks, rocking->node}
                   : std::pair{ImplicitMotion::kHoldsItsShape, Index{-1}};
  }
  const bool free_piece = std::any_of(pieces.piece.begin(), pieces.piece.end(),
                                      [&](Index piece) { return pieces.held[piece] == 0; });
  if (!free_piece) {
    return {ImplicitMotion::kSwings, -1};
  }
  const bool something_to_land_on = model.ground.enabled || model.contact.enabled;
  return {something_to_land_on ? ImplicitMotion::kFolds : ImplicitMotion::kTumbles, -1};
}

}  // namespace

ImplicitMotion expected_motion(const Model& model) {
  return expected_motion_and_node(model).first;
}

double estimate_margin(ImplicitMotion motion) {
  return motion == ImplicitMotion::kSwings ? 1.0 : kFreeStructureMargin;
}

ImplicitStepCounts assumed_step_counts(ImplicitMotion motion) {
  switch (motion) {
    case ImplicitMotion::kHoldsItsShape:
      return {4.0, 35.0, 0.1};
    case ImplicitMotion::kRocks:
      return {5.0, 60.0, 0.3};
    case ImplicitMotion::kFolds:
    case ImplicitMotion::kTumbles:
      return {14.0, 140.0, 1.0};
    case ImplicitMotion::kSwings:
      break;
  }
  return {6.0, 70.0, 0.8};
}

std::string motion_text(const ImplicitStepCost& cost) {
  switch (cost.motion) {
    case ImplicitMotion::kHoldsItsShape:
      return "its bars hold its shape";
    case ImplicitMotion::kRocks:
      return fmt::format(
          "its bars hold its shape, but a piece of it lands off balance (the piece of node {}): "
          "it rocks, rolls or topples",
          cost.off_balance_node);
    case ImplicitMotion::kFolds:
      return "its bars leave some of its motions to the bending and torsion springs, and it "
             "lands: it folds";
    case ImplicitMotion::kTumbles:
      return "no pin holds it, its bars do not hold its shape, and it has nothing to land on: "
             "it tumbles";
    case ImplicitMotion::kSwings:
      break;
  }
  return "held by its pins: it swings";
}

namespace {

// The factor is found from the free nodes' graph, not from the 3n × 3n Hessian: every spring
// joins its nodes in 3 × 3 blocks, so the Hessian's pattern is the graph's with each entry a
// dense block, and a node's column of the graph's factor with c entries (its diagonal among
// them) stands for three columns of the Hessian's with 3(c − 1) + 3, + 2 and + 1. No values
// are assembled: the analysis takes memory and time of the order of the springs' count.
HessianFactorSize analyse_factor(const Model& model, const FreeDofs& dofs) {
  HessianFactorSize size;
  size.unknowns = static_cast<double>(dofs.count);
  if (dofs.count == 0) {
    return size;
  }
  const Index free_nodes = dofs.count / 3;
  const auto column_of = [&](Index node) { return dofs.first_dof[node] / 3; };  // −1: pinned
  // Every pair of free nodes within one spring, as (column, row) of the graph's lower triangle.
  const auto for_each_pair = [&](const auto& visit) {
    const auto stencil = [&](const Index* nodes, int count) {
      for (int a = 0; a < count; ++a) {
        for (int b = a + 1; b < count; ++b) {
          const Index u = column_of(nodes[a]);
          const Index v = column_of(nodes[b]);
          if (u >= 0 && v >= 0 && u != v) {
            visit(std::min(u, v), std::max(u, v));
          }
        }
      }
    };
    for (Index s = 0; s < model.bar_count(); ++s) {
      stencil(&model.bar_nodes[2 * s], 2);
    }
    for (Index s = 0; s < model.bend_count(); ++s) {
      stencil(&model.bend_nodes[3 * s], 3);
    }
    for (Index s = 0; s < model.torsion_count(); ++s) {
      stencil(&model.torsion_nodes[4 * s], 4);
    }
  };
  // Compressed columns: the diagonal, then each pair once.
  std::vector<int> start(static_cast<std::size_t>(free_nodes) + 1, 0);
  for (Index j = 0; j < free_nodes; ++j) {
    start[j + 1] = 1;
  }
  for_each_pair([&](Index column, Index) { ++start[column + 1]; });
  for (Index j = 0; j < free_nodes; ++j) {
    start[j + 1] += start[j];
  }
  std::vector<int> rows(static_cast<std::size_t>(start.back()));
  std::vector<int> next(start.begin(), start.end() - 1);
  for (Index j = 0; j < free_nodes; ++j) {
    rows[next[j]++] = j;
  }
  for_each_pair([&](Index column, Index row) { rows[next[column]++] = row; });
  int kept = 0;
  for (Index j = 0; j < free_nodes; ++j) {
    const auto first = rows.begin() + start[j];
    auto last = rows.begin() + start[j + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    start[j] = kept;
    kept = static_cast<int>(std::copy(first, last, rows.begin() + kept) - rows.begin());
  }
  start[free_nodes] = kept;
  rows.resize(static_cast<std::size_t>(kept));
  // Each free node's diagonal block and each pair's two, of 9 entries.
  size.hessian_nonzeros = 9.0 * (2.0 * kept - static_cast<double>(free_nodes));

  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  // The best of AMD and METIS orders, as CHOLMOD's default choice for the 3n × 3n Hessian finds
  // them (on the graph alone its default stops at AMD, whose factor is 23 % larger for a cloth of
  // 150 000 bars).
  common.nmethods = 3;
  cholmod_sparse graph{};
  graph.nrow = graph.ncol = static_cast<std::size_t>(free_nodes);
  graph.nzmax = rows.size();
  graph.p = start.data();
  graph.i = rows.data();
  graph.stype = -1;  // symmetric, its lower triangle given
  graph.itype = CHOLMOD_INT;
  graph.xtype = CHOLMOD_PATTERN;
  graph.dtype = CHOLMOD_DOUBLE;
  graph.sorted = 1;
  graph.packed = 1;
  cholmod_factor* factor = cholmod_analyze(&graph, &common);
  DINAM_CHECK(factor != nullptr);
  const int* counts = static_cast<const int*>(factor->ColCount);
  for (Index j = 0; j < free_nodes; ++j) {
    const double below = 3.0 * (counts[j] - 1);
    size.nonzeros += 3.0 * below + 6.0;
    for (int k = 1; k <= 3; ++k) {
      size.flops += (below + k) * (below + k);  // a simplicial column's: its count squared
    }
  }
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  return size;
}

// What the analysis depends on: the springs' nodes and which nodes are free (FNV-1a over them).
std::uint64_t graph_key(const Model& model, const FreeDofs& dofs) {
  std::uint64_t key = 14695981039346656037ULL;
  const auto mix = [&](const std::vector<Index>& values) {
    for (const Index value : values) {
      key = (key ^ static_cast<std::uint32_t>(value)) * 1099511628211ULL;
    }
    key = (key ^ values.size()) * 1099511628211ULL;
  };
  mix(model.bar_nodes);
  mix(model.bend_nodes);
  mix(model.torsion_nodes);
  mix(dofs.first_dof);
  return key;
}

}  // namespace

HessianFactorSize hessian_factor_size(const Model& model) {
  // The analysis takes seconds on a model of a million bars, and one `info` asks for it up to
  // five times (the memory of a render and of a simulation, the run's time, the integrators
  // side by side): the last one is kept, for the same springs on the same free nodes.
  static std::mutex guard;
  static std::optional<std::pair<std::uint64_t, HessianFactorSize>> last;
  const FreeDofs dofs = free_dofs(model);
  const std::uint64_t key = graph_key(model, dofs);
  {
    const std::lock_guard lock(guard);
    if (last && last->first == key) {
      return last->second;
    }
  }
  const HessianFactorSize size = analyse_factor(model, dofs);
  const std::lock_guard lock(guard);
  last = {key, size};
  return size;
}

ImplicitStepCost estimate_implicit_step(const Model& model, const StepCost& forces) {
  ImplicitStepCost cost;
  cost.factor = hessian_factor_size(model);
  const auto springs =
      static_cast<double>(model.bar_count() + model.bend_count() + model.torsion_count());
  cost.factorization_seconds =
      1e-9 * (measured::kNsPerFlop * cost.factor.flops + measured::kAssemblyNsPerSpring * springs);
  cost.iteration_seconds = 1e-9 * measured::kForceEvaluationsPerIteration * forces.serial_ns;
  cost.solve_iteration_seconds =
      1e-9 * (forces.serial_ns + measured::kNsPerSolveCall +
              2.0 * measured::kNsPerFactorNonzero * cost.factor.nonzeros);
  std::tie(cost.motion, cost.off_balance_node) = expected_motion_and_node(model);
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
