#include "estimate/solver_memory.hpp"

#include <Eigen/SparseCore>
#include <algorithm>

#include "dynamics/stiffness.hpp"
#include "estimate/implicit_cost.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Measured (heaptrack, `dinam simulate` of an implicit run): CHOLMOD's supernodal factor, with its
// indices, padding and workspace, took 11.9 bytes a nonzero of the simplicial count
// (hessian_factor_size) on a 100 × 100 cloth, 11.0 on a 200 × 200 cloth and on the Wuson.
constexpr double kFactorBytesPerNonzero = 12.0;
// A compressed sparse matrix: a value and a row index an entry, a start a column.
constexpr double kMatrixBytesPerNonzero = sizeof(double) + sizeof(int);
// The implicit integrator's vectors, a node's worth: about 40 of its three coordinates (the
// step's states, Newton's and the conjugate gradients' vectors).
constexpr double kVectorBytesPerNode = 40 * 3 * sizeof(double);
// A damper's triplet and the entry it is kept at (solver/triplet_matrix.hpp).
constexpr double kTripletBytes = sizeof(Eigen::Triplet<double>) + 3 * sizeof(Index);

}  // namespace

std::uint64_t newton_bytes(const Model& model, const HessianFactorSize& factor) {
  // A chunk of each kind's springs' matrices, (3 k)² doubles for a spring of k nodes, kept kind
  // by kind (dynamics/stiffness.hpp).
  const auto chunk = [](Index count) {
    return static_cast<double>(std::min(count, kStiffnessChunk));
  };
  const double element_matrices =
      sizeof(double) * (36.0 * (chunk(model.bar_count()) + chunk(model.clamp_count())) +
                        81.0 * chunk(model.bend_count()) + 144.0 * chunk(model.torsion_count()));
  const double columns = factor.unknowns + 1.0;
  const double hessian = kMatrixBytesPerNonzero * factor.hessian_nonzeros + sizeof(int) * columns;
  const double pattern = sizeof(int) * (factor.hessian_nonzeros + columns);
  return static_cast<std::uint64_t>(element_matrices + 2.0 * hessian + pattern +
                                    kFactorBytesPerNonzero * factor.nonzeros);
}

std::uint64_t implicit_integrator_bytes(const Model& model) {
  const HessianFactorSize factor = hessian_factor_size(model);
  // The bars' axial dampers: a bar's four blocks as triplets, and the matrix they are set into.
  const double dampers = model.any_bar_damping ? 36.0 * static_cast<double>(model.bar_count()) *
                                                     (kTripletBytes + kMatrixBytesPerNonzero)
                                               : 0.0;
  return newton_bytes(model, factor) +
         static_cast<std::uint64_t>(dampers + kVectorBytesPerNode * model.node_count());
}

}  // namespace dinam
