#include "dynamics/field_forces.hpp"

#include "model/model.hpp"

namespace dinam {

void add_gravity_forces(const Model& model, std::vector<Vec3>& force) {
  const Index n = model.node_count();
  for (Index i = 0; i < n; ++i) {
    force[i] += model.node_mass[i] * model.gravity;
  }
}

}  // namespace dinam
