#include "dynamics/free_dofs.hpp"

#include "model/model.hpp"

namespace dinam {

Eigen::VectorXd free_part(const FreeDofs& dofs, const std::vector<Vec3>& per_node) {
  Eigen::VectorXd v;
  free_part(dofs, per_node, v);
  return v;
}

void free_part(const FreeDofs& dofs, const std::vector<Vec3>& per_node, Eigen::VectorXd& free) {
  free.resize(dofs.count);
  for (std::size_t i = 0; i < per_node.size(); ++i) {
    if (dofs.first_dof[i] >= 0) {
      free.segment<3>(dofs.first_dof[i]) = per_node[i];
    }
  }
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

}  // namespace dinam
