#include "dynamics/axial_spring.hpp"

#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {

void add_axial_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  State& state = context.state;
  for_each_spring_by_colour(model.bar_colours, [&](Index b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const AxialSpringResult r = axial_spring(state.x[n0], state.x[n1], model.bar_rest_length[b],
                                             model.bar_axial_stiffness[b], state.bar_plastic_set[b],
                                             model.bar_yield_force[b]);
    context.force[n0] += r.force_on_n0;
    context.force[n1] -= r.force_on_n0;
    context.record_plastic_flow(b, state.bar_plastic_set[b], r.plastic_set, r.dissipated);
  });
  context.book_plastic_flow(model.bar_colours);
}

void add_axial_damper_forces(ForceContext& context) {
  const Model& model = context.model;
  const State& state = context.state;
  for_each_spring_by_colour(model.bar_colours, [&](Index b) {
    if (model.bar_damping[b] == 0.0) {
      return;
    }
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const Vec3 f0 = axial_damper(state.x[n0], state.x[n1], state.v_half[n0], state.v_half[n1],
                                 model.bar_damping[b]);
    context.force[n0] += f0;
    context.force[n1] -= f0;
  });
}

double axial_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index b = 0; b < model.bar_count(); ++b) {
    energy += axial_spring(state.x[model.bar_nodes[2 * b]], state.x[model.bar_nodes[2 * b + 1]],
                           model.bar_rest_length[b], model.bar_axial_stiffness[b],
                           state.bar_plastic_set[b], model.bar_yield_force[b])
                  .energy;
  }
  return energy;
}

}  // namespace dinam
