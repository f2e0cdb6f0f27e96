#include "dynamics/energy.hpp"

#include "model/model.hpp"

namespace dinam {

double kinetic_energy(const Model& model, const std::vector<Vec3>& v) {
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      energy += 0.5 * model.node_mass[i] * v[i].squaredNorm();
    }
  }
  return energy;
}

double gravitational_energy(const Model& model, const std::vector<Vec3>& x) {
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    energy -= model.node_mass[i] * model.gravity.dot(x[i]);
  }
  return energy;
}

}  // namespace dinam
