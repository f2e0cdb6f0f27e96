#include "dynamics/axial_spring.hpp"

#include "dynamics/parallel_loops.hpp"
#include "dynamics/spring_block.hpp"
#include "model/model.hpp"

namespace dinam {

void add_axial_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  const SpringArrays springs{model.bar_colours,
                             model.bar_nodes,
                             model.bar_rest_length,
                             model.bar_axial_stiffness,
                             model.bar_yield_force,
                             context.state.bar_plastic_set,
                             broken_flags(context.state.bar_broken)};
  add_spring_forces<2>(
      context, springs,
      [](SpringBlock<2> & block, Index k, double rest, double stiffness, double plastic_set,
         double yield) __attribute__((always_inline)) {
        const AxialSpringResult r =
            axial_spring(block.node_position(0, k), block.node_position(1, k), rest, stiffness,
                         plastic_set, yield);
        block.set_force(0, k, r.force_on_n0);
        block.set_force(1, k, -r.force_on_n0);
        block.new_plastic_set[k] = r.plastic_set;
        block.dissipated[k] = r.dissipated;
      });
}

void add_axial_damper_forces(ForceContext& context) {
  const Model& model = context.model;
  const State& state = context.state;
  if (!model.any_bar_damping) {
    return;
  }
  const std::uint8_t* broken = broken_flags(state.bar_broken);
  // Block by block as the springs (spring_block.hpp): gather both ends' positions and velocities,
  // compute one damper per lane, add to the nodes in the colouring's order.
  for_each_spring_block(model.bar_colours, [&](Index first, Index count) {
    SpringBlock<2> positions;
    SpringBlock<2> velocities;
    const Index* ends = &model.bar_nodes[2 * static_cast<std::size_t>(first)];
    for (Index k = 0; k < count; ++k) {
      for (int j = 0; j < 2; ++j) {
        positions.set_position(j, k, state.x[ends[2 * k + j]]);
        velocities.set_position(j, k, state.v_half[ends[2 * k + j]]);
      }
    }
    const double* coefficient = &model.bar_damping[first];
    for (Index k = 0; k < count; ++k) {
      positions.set_force(0, k,
                          axial_damper(positions.node_position(0, k), positions.node_position(1, k),
                                       velocities.node_position(0, k),
                                       velocities.node_position(1, k), coefficient[k]));
    }
    for (Index k = 0; k < count; ++k) {
      if (coefficient[k] == 0.0 || (broken != nullptr && broken[first + k] != 0)) {
        continue;
      }
      const Vec3 f0 = positions.node_force(0, k);
      context.add(ends[2 * k], f0);
      context.add(ends[2 * k + 1], -f0);
    }
  });
}

double axial_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index b = 0; b < model.bar_count(); ++b) {
    if (!state.bar_broken.empty() && state.bar_broken[b] != 0) {
      continue;
    }
    energy += axial_spring(state.x[model.bar_nodes[2 * b]], state.x[model.bar_nodes[2 * b + 1]],
                           model.bar_rest_length[b], model.bar_axial_stiffness[b],
                           state.bar_plastic_set[b], model.bar_yield_force[b])
                  .energy;
  }
  return energy;
}

}  // namespace dinam
