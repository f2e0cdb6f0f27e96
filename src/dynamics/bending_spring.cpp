#include "dynamics/bending_spring.hpp"

#include "dynamics/integrator.hpp"
#include "dynamics/spring_block.hpp"
#include "model/model.hpp"

namespace dinam {

void add_bending_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  const SpringArrays springs{model.bend_count(),
                             model.bends_yield,
                             &MemberShare::bends,
                             model.bend_nodes,
                             model.bend_rest_angle,
                             model.bend_stiffness,
                             model.bend_yield_moment,
                             context.state.bend_plastic_set,
                             broken_flags(context.state.bend_broken),
                             flow_record(context, context.state.energy_workspace.bend_flow)};
  add_spring_forces<3>(
      context, springs,
      [](SpringBlock<3> & block, Index k, double rest, double stiffness, double plastic_set,
         double yield) __attribute__((always_inline)) {
        const BendingSpringResult r =
            bending_spring(block.node_position(0, k), block.node_position(1, k),
                           block.node_position(2, k), rest, stiffness, plastic_set, yield);
        block.set_force(0, k, r.force_a);
        block.set_force(1, k, r.force_c);
        block.set_force(2, k, r.force_b);
        block.new_plastic_set[k] = r.plastic_set;
        block.dissipated[k] = r.dissipated;
      });
}

double bending_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index s = 0; s < model.bend_count(); ++s) {
    if (!state.bend_broken.empty() && state.bend_broken[s] != 0) {
      continue;
    }
    const Index* nodes = &model.bend_nodes[3 * s];
    energy += bending_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]],
                             model.bend_rest_angle[s], model.bend_stiffness[s],
                             plastic_set_of(state.bend_plastic_set, s),
                             yield_limit(model.bend_yield_moment, s))
                  .energy;
  }
  return energy;
}

const SpringKind kBendingSprings{
    .name = "bending springs",
    .switched = &ForceSwitches::bending,
    .count = [](const Model& model) { return model.bend_count(); },
    .yields = [](const Model& model) { return model.bends_yield; },
    .add_forces = add_bending_spring_forces,
    .energy = bending_spring_energy,
    .report = &EnergyReport::bending,
    .plastic_set = &State::bend_plastic_set,
    .flow = &EnergyWorkspace::bend_flow,
    .broken = &State::bend_broken,
    .torn_code = kTornBend,
    .ns_per_item = 14.5,
    .ns_per_item_yielding = 18.2,
};

}  // namespace dinam
