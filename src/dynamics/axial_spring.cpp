#include "dynamics/axial_spring.hpp"

#include "model/model.hpp"

namespace dinam {

void add_axial_spring_forces(const Model& model, const std::vector<Vec3>& x,
                             std::vector<Vec3>& force) {
  const Index n_bars = model.bar_count();
  for (Index b = 0; b < n_bars; ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const AxialSpringResult r =
        axial_spring(x[n0], x[n1], model.bar_rest_length[b], model.bar_axial_stiffness[b]);
    force[n0] += r.force_on_n0;
    force[n1] -= r.force_on_n0;
  }
}

double axial_spring_energy(const Model& model, const std::vector<Vec3>& x) {
  double energy = 0.0;
  for (Index b = 0; b < model.bar_count(); ++b) {
    energy += axial_spring(x[model.bar_nodes[2 * b]], x[model.bar_nodes[2 * b + 1]],
                           model.bar_rest_length[b], model.bar_axial_stiffness[b])
                  .energy;
  }
  return energy;
}

}  // namespace dinam
