#include "solver/rigid_motions.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "model/mesh_pieces.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// Singular values of a piece's pin constraints below this share of the largest are a motion
// the pins leave: the constraints' entries are 1 and offsets over the piece's size (at most 1),
// so a left motion's value is round-off, near 1e-16.
constexpr double kConstraintRank = 1e-9;
// A left motion that moves the free nodes by less than this share of the piece's free mass
// times its size² moves none of them (the turn of a straight rope about its own line).
constexpr double kMovesNothing = 1e-12;

// The rigid motion k ∈ [0, 6) at a point r − c from the centre, of a piece of `size`: the
// translations along x, y, z, then the turns about them, scaled so that a unit turn moves the
// piece's farthest point by about 1 m as a unit translation does.
Vec3 generator(int k, const Vec3& offset, double size) {
  if (k < 3) {
    return Vec3::Unit(k);
  }
  return Vec3::Unit(k - 3).cross(offset) / size;
}

}  // namespace

RigidMotions::RigidMotions(const Model& model, const std::vector<Vec3>& x, const FreeDofs& dofs)
    : free_first_dof_(dofs.first_dof), node_mass_(model.node_mass) {
  const MeshPieces mesh = mesh_pieces(model);
  const std::vector<Index> order = nodes_by_piece(mesh);
  for (std::size_t first = 0; first < order.size();) {
    const std::size_t end = first + static_cast<std::size_t>(mesh.size[mesh.piece[order[first]]]);
    std::vector<Index> free_nodes;
    std::vector<Index> pins;
    double mass = 0.0;
    Vec3 moment = Vec3::Zero();
    for (std::size_t k = first; k < end; ++k) {
      const Index i = order[k];
      if (dofs.first_dof[i] >= 0) {
        free_nodes.push_back(i);
        mass += model.node_mass[i];
        moment += model.node_mass[i] * x[i];
      } else {
        pins.push_back(i);
      }
    }
    first = end;
    if (free_nodes.empty() || mass <= 0.0) {
      continue;
    }
    const Vec3 centre = moment / mass;
    Piece piece;
    double size = 0.0;
    for (const Index i : free_nodes) {
      piece.first_dof.push_back(dofs.first_dof[i]);
      piece.mass.push_back(model.node_mass[i]);
      piece.offset.push_back(x[i] - centre);
      size = std::max(size, piece.offset.back().norm());
    }
    for (const Index i : pins) {
      size = std::max(size, (x[i] - centre).norm());
    }
    piece.size = size > 0.0 ? size : 1.0;

    // The motions the pins leave: the null space of "each pin stays where it is".
    Eigen::MatrixXd left = Matrix6::Identity();
    if (!pins.empty()) {
      Eigen::MatrixXd constraints(3 * static_cast<Eigen::Index>(pins.size()), 6);
      for (std::size_t p = 0; p < pins.size(); ++p) {
        for (int k = 0; k < 6; ++k) {
          constraints.block<3, 1>(3 * static_cast<Eigen::Index>(p), k) =
              generator(k, x[pins[p]] - centre, piece.size);
        }
      }
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(constraints, Eigen::ComputeFullV);
      const Eigen::VectorXd& values = svd.singularValues();
      int rank = 0;
      while (rank < values.size() && values[rank] > kConstraintRank * values[0]) {
        ++rank;
      }
      left = svd.matrixV().rightCols(6 - rank);
    }
    if (left.cols() == 0) {
      continue;
    }
    // Their Gram matrix in M over the free nodes; an M-orthonormal basis of those that move any.
    Matrix6 gram = Matrix6::Zero();
    for (std::size_t k = 0; k < piece.offset.size(); ++k) {
      Eigen::Matrix<double, 3, 6> g;
      for (int c = 0; c < 6; ++c) {
        g.col(c) = generator(c, piece.offset[k], piece.size);
      }
      gram += piece.mass[k] * g.transpose() * g;
    }
    const Eigen::MatrixXd reduced = left.transpose() * gram * left;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(reduced);
    std::vector<Eigen::Index> kept;
    for (Eigen::Index k = 0; k < reduced.rows(); ++k) {
      if (eigen.eigenvalues()[k] > kMovesNothing * mass) {
        kept.push_back(k);
      }
    }
    if (kept.empty()) {
      continue;
    }
    piece.basis.resize(6, static_cast<Eigen::Index>(kept.size()));
    for (std::size_t k = 0; k < kept.size(); ++k) {
      piece.basis.col(static_cast<Eigen::Index>(k)) =
          left * eigen.eigenvectors().col(kept[k]) / std::sqrt(eigen.eigenvalues()[kept[k]]);
    }
    count_ += static_cast<int>(kept.size());
    pieces_.push_back(std::move(piece));
  }
}

double RigidMotions::rigid_share(const Eigen::VectorXd& shape) const {
  double total = 0.0;  // φᵀ M φ
  for (std::size_t i = 0; i < node_mass_.size(); ++i) {
    if (free_first_dof_[i] >= 0) {
      total += node_mass_[i] * shape.segment<3>(free_first_dof_[i]).squaredNorm();
    }
  }
  if (total <= 0.0) {
    return 0.0;
  }
  double rigid = 0.0;  // the M-norm² of φ's projection on the rigid motions, piece by piece
  for (const Piece& piece : pieces_) {
    Vector6 moments = Vector6::Zero();  // Gᵀ M φ
    for (std::size_t k = 0; k < piece.offset.size(); ++k) {
      const Vec3 weighted = piece.mass[k] * shape.segment<3>(piece.first_dof[k]);
      for (int c = 0; c < 6; ++c) {
        moments[c] += generator(c, piece.offset[k], piece.size).dot(weighted);
      }
    }
    rigid += (piece.basis.transpose() * moments).squaredNorm();
  }
  return std::clamp(rigid / total, 0.0, 1.0);
}

}  // namespace dinam
