#pragma once
// The rigid motions a structure's pins leave it: for each piece of its mesh (model/mesh_pieces),
// the translations and turns v_i = t + θ × (x_i − c) that keep every pin of the piece in place
// (all six for a piece no pin holds, the turns about a pin for one held at a point, the turn about
// the line through its pins for a hinge, none for one held at three points off a line). A natural
// mode that is such a motion deforms nothing, so only loads (gravity through a pendulum's pin, the
// ground's penalty) can give it a frequency; the modes' table tells those from the motions nothing
// resists by this measure, which does not depend on how stiff the stiffest bar is.
#include <Eigen/Core>
#include <vector>

#include "core/types.hpp"
#include "dynamics/free_dofs.hpp"

namespace dinam {

struct Model;

class RigidMotions {
 public:
  RigidMotions(const Model& model, const std::vector<Vec3>& x, const FreeDofs& dofs);

  // The share of `shape`'s kinetic norm φᵀ M φ that rigid motions of the pieces hold, in [0, 1]:
  // 1 for a motion that deforms nothing, 0 for one orthogonal (in M) to every rigid motion.
  // `shape` over the free dofs, as `dofs` orders them.
  double rigid_share(const Eigen::VectorXd& shape) const;

  // The rigid motions left, over all pieces (0 for a structure held fast).
  int count() const { return count_; }

 private:
  struct Piece {
    std::vector<Index> first_dof;  // (n_free) its free nodes' x dofs
    std::vector<double> mass;      // (n_free) kg
    std::vector<Vec3> offset;      // (n_free) m, x − c from its free nodes' centre of mass c
    double size = 1.0;             // m, turns are measured as θ × size, so both kinds weigh alike
    // (6 × r) the rigid motions its pins leave, over (t, θ size), orthonormal in M.
    Eigen::MatrixXd basis;
  };

  std::vector<Index> free_first_dof_;  // (n_nodes) as FreeDofs::first_dof
  std::vector<double> node_mass_;      // (n_nodes) kg
  std::vector<Piece> pieces_;
  int count_ = 0;
};

}  // namespace dinam
