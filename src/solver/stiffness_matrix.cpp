#include "solver/stiffness_matrix.hpp"

#include <Eigen/Eigenvalues>

#include "core/error.hpp"
#include "dynamics/ground_contact.hpp"
#include "dynamics/object_contact.hpp"
#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// An element's matrix with its negative eigenvalues set to zero: V max(Λ, 0) Vᵀ.
template <int kSize>
void project_to_semidefinite(double* stiffness) {
  using Matrix = Eigen::Matrix<double, kSize, kSize>;
  Eigen::Map<Matrix> k(stiffness);
  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(k);
  if (eigen.eigenvalues().minCoeff() >= 0.0) {
    return;
  }
  k = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
      eigen.eigenvectors().transpose();
}

// Hands each element's 3 × 3 blocks between free nodes to the triplets.
class TripletSink final : public StiffnessSink {
 public:
  TripletSink(const FreeDofs& dofs, Definiteness definiteness,
              std::vector<Eigen::Triplet<double>>& triplets)
      : dofs_(dofs), definiteness_(definiteness), triplets_(triplets) {}

  void add(const Index* nodes, int node_count, const double* stiffness) override {
    const int size = 3 * node_count;
    scratch_.assign(stiffness, stiffness + static_cast<std::ptrdiff_t>(size) * size);
    if (definiteness_ == Definiteness::kProjected) {
      switch (node_count) {
        case 1:
          project_to_semidefinite<3>(scratch_.data());
          break;
        case 2:
          project_to_semidefinite<6>(scratch_.data());
          break;
        case 3:
          project_to_semidefinite<9>(scratch_.data());
          break;
        case 4:
          project_to_semidefinite<12>(scratch_.data());
          break;
        default:
          DINAM_CHECK(false);
      }
    }
    for (int col_node = 0; col_node < node_count; ++col_node) {
      const Index col_dof = dofs_.first_dof[nodes[col_node]];
      if (col_dof < 0) {
        continue;
      }
      for (int row_node = 0; row_node < node_count; ++row_node) {
        const Index row_dof = dofs_.first_dof[nodes[row_node]];
        if (row_dof < 0) {
          continue;
        }
        for (int b = 0; b < 3; ++b) {
          for (int a = 0; a < 3; ++a) {
            const std::size_t column = 3 * static_cast<std::size_t>(col_node) + b;
            const double value = scratch_[column * size + 3 * row_node + a];
            triplets_.emplace_back(row_dof + a, col_dof + b, value);
          }
        }
      }
    }
  }

 private:
  const FreeDofs& dofs_;
  Definiteness definiteness_;
  std::vector<Eigen::Triplet<double>>& triplets_;
  std::vector<double> scratch_;
};

}  // namespace

Eigen::VectorXd free_part(const FreeDofs& dofs, const std::vector<Vec3>& per_node) {
  Eigen::VectorXd v(dofs.count);
  for (std::size_t i = 0; i < per_node.size(); ++i) {
    if (dofs.first_dof[i] >= 0) {
      v.segment<3>(dofs.first_dof[i]) = per_node[i];
    }
  }
  return v;
}

FreeDofs free_dofs(const Model& model) {
  FreeDofs dofs;
  dofs.first_dof.assign(static_cast<std::size_t>(model.node_count()), -1);
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      dofs.first_dof[i] = dofs.count;
      dofs.count += 3;
    }
  }
  return dofs;
}

Eigen::VectorXd free_masses(const Model& model, const FreeDofs& dofs) {
  Eigen::VectorXd mass(dofs.count);
  for (Index i = 0; i < model.node_count(); ++i) {
    if (dofs.first_dof[i] >= 0) {
      mass.segment<3>(dofs.first_dof[i]).setConstant(model.node_mass[i]);
    }
  }
  return mass;
}

const SparseMatrix& StiffnessAssembly::assemble(const Model& model, const State& state,
                                                const ForceSwitches& switches, const FreeDofs& dofs,
                                                Definiteness definiteness) {
  triplets_.clear();
  // Every free node's diagonal block, so that the pattern does not change with the ground.
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index dof = dofs.first_dof[i];
    for (int b = 0; b < 3 && dof >= 0; ++b) {
      for (int a = 0; a < 3; ++a) {
        triplets_.emplace_back(dof + a, dof + b, 0.0);
      }
    }
  }
  TripletSink sink(dofs, definiteness, triplets_);
  for (const SpringKind* kind : kSpringKinds) {
    if (switches.*kind->switched) {
      kind->add_stiffness(model, state, sink);
    }
  }
  if (switches.ground) {
    add_ground_contact_stiffness(model, state, sink);
  }
  if (switches.object_contact) {
    add_object_contact_stiffness(model, state, sink);
  }
  matrix_.resize(dofs.count, dofs.count);
  matrix_.setFromTriplets(triplets_.begin(), triplets_.end());
  return matrix_;
}

}  // namespace dinam
