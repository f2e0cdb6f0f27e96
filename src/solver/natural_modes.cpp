#include "solver/natural_modes.hpp"

#include <fmt/format.h>

#include <Spectra/SymEigsShiftSolver.h>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/rigid_motions.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Models with at most this many free degrees of freedom are solved densely (all modes at once,
// exactly): Lanczos needs a subspace of a few times the modes asked for, which small models do
// not have.
constexpr Index kLargestDense = 600;

// The shift below which Lanczos looks, as a share of the mean ω²_ii: just below zero, so that
// A − σI is positive definite for a stable structure (zero-frequency modes of a free one
// included) and the modes nearest σ are the lowest.
constexpr double kShiftShare = 1e-8;

// Spectra's operator y = (A − σI)⁻¹ x: a Cholesky factorisation where A − σI is positive definite
// (a stable equilibrium), else an LDLᵀ one (an unstable equilibrium, whose modes below σ grow).
class ShiftSolve {
 public:
  using Scalar = double;
  explicit ShiftSolve(const SparseMatrix& a) : a_(a) {}
  Eigen::Index rows() const { return a_.rows(); }
  Eigen::Index cols() const { return a_.cols(); }
  void set_shift(double sigma) {
    SparseMatrix shifted = a_;
    shifted.diagonal().array() -= sigma;
    definite_ = cholesky_.factorize(shifted);
    if (!definite_) {
      indefinite_.compute(shifted);
      if (indefinite_.info() != Eigen::Success) {
        throw RuntimeError("the natural modes: the stiffness could not be factorised at the shift");
      }
    }
  }
  void perform_op(const double* x, double* y) const {
    stop_if_asked();  // Spectra's iterations: one solve each
    const Eigen::Map<const Vector> in(x, a_.rows());
    Eigen::Map<Vector>(y, a_.rows()) = definite_ ? cholesky_.solve(in) : indefinite_.solve(in);
  }

 private:
  const SparseMatrix& a_;
  PositiveDefiniteSolver cholesky_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> indefinite_;
  bool definite_ = true;
};

// A mode is free where at least this share of its kinetic norm is a rigid motion (the rest is
// the eigenvector's round-off, near 1e-10 of it where the next mode is well apart) ...
constexpr double kRigidShare = 1.0 - 1e-6;
// ... and its |ω²| is below this share of the loads' scale |g| / size (a pendulum of the
// structure's size swings at about that ω²: a rigid motion below a millionth of it is one no load
// holds) ...
constexpr double kLoadShare = 1e-6;
// ... or below this share of ω_max² (frequency_bound.hpp), the eigensolver's round-off: the free
// motions of a steel cable of 400 bars came out at 1e-17 of it, those of a tetrahedron 1e-15.
constexpr double kRoundOffShare = 1e-14;

struct Eigenpairs {
  Vector values;            // ascending
  Eigen::MatrixXd vectors;  // orthonormal columns
};

Eigenpairs lowest_dense(const SparseMatrix& a, int count) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(a)};
  return {solver.eigenvalues().head(count), solver.eigenvectors().leftCols(count)};
}

Eigenpairs lowest_by_lanczos(const SparseMatrix& a, int count) {
  ShiftSolve op(a);
  const double sigma = -kShiftShare * a.diagonal().mean();
  const auto n = static_cast<int>(a.rows());
  const int subspace = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymEigsShiftSolver<ShiftSolve> eigs(op, count, subspace, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful) {
    throw RuntimeError(fmt::format(
        "the natural modes: Lanczos did not converge on the lowest {} modes ({} free degrees of "
        "freedom); ask for fewer with --count",
        count, n));
  }
  return {eigs.eigenvalues(), eigs.eigenvectors()};
}

}  // namespace

std::vector<NaturalMode> natural_modes(const Model& model, const State& state,
                                       const ForceSwitches& switches, int count) {
  const FreeDofs dofs = free_dofs(model);
  count = std::min<int>(count, dofs.count);
  if (count <= 0) {
    return {};
  }
  // A = M^{-½} K M^{-½}: its eigenvalues are ω², its eigenvectors M^{½} φ.
  const Vector inverse_root_mass = free_masses(model, dofs).cwiseSqrt().cwiseInverse();
  // The forces once, for the pairs of objects touching there.
  State at = state;
  compute_static_forces(model, switches, at);
  StiffnessAssembly assembly;
  const SparseMatrix k = assembly.assemble(model, at, switches, dofs, Definiteness::kExact);
  SparseMatrix a = inverse_root_mass.asDiagonal() * k;
  a = a * inverse_root_mass.asDiagonal();
  const Eigenpairs pairs =
      dofs.count <= kLargestDense ? lowest_dense(a, count) : lowest_by_lanczos(a, count);

  double free_mass = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    free_mass += dofs.first_dof[i] >= 0 ? model.node_mass[i] : 0.0;
  }
  const RigidMotions rigid(model, state.x, dofs);
  Vec3 low = state.x.front();
  Vec3 high = state.x.front();
  for (const Vec3& p : state.x) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double size = std::max((high - low).norm(), 1e-6);
  const double free_below = std::max(kLoadShare * model.gravity.norm() / size,
                                     kRoundOffShare * max_frequency_squared_bound(model));
  std::vector<NaturalMode> modes;
  for (int m = 0; m < count; ++m) {
    NaturalMode mode;
    mode.omega_squared = pairs.values[m];
    Vector phi = inverse_root_mass.cwiseProduct(pairs.vectors.col(m));
    mode.free = rigid.count() > 0 && std::abs(mode.omega_squared) <= free_below &&
                rigid.rigid_share(phi) >= kRigidShare;
    mode.frequency = mode.omega_squared > 0.0 && !mode.free
                         ? std::sqrt(mode.omega_squared) / (2.0 * std::numbers::pi)
                         : 0.0;
    Eigen::Index largest = 0;
    phi.cwiseAbs().maxCoeff(&largest);
    if (phi[largest] < 0.0) {
      phi = -phi;
    }
    mode.shape.assign(static_cast<std::size_t>(model.node_count()), Vec3::Zero());
    Vec3 participation = Vec3::Zero();  // Γ = φᵀ M r for r each axis
    for (Index i = 0; i < model.node_count(); ++i) {
      if (dofs.first_dof[i] >= 0) {
        mode.shape[i] = phi.segment<3>(dofs.first_dof[i]);
        participation += model.node_mass[i] * mode.shape[i];
      }
    }
    mode.mass_share = participation.cwiseProduct(participation) / free_mass;
    modes.push_back(std::move(mode));
  }
  std::sort(modes.begin(), modes.end(), [](const NaturalMode& p, const NaturalMode& q) {
    return p.omega_squared < q.omega_squared;
  });
  return modes;
}

}  // namespace dinam
