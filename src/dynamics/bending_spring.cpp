#include "dynamics/bending_spring.hpp"

#include "dynamics/broken.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/spring_block.hpp"
#include "estimate/measured_costs.hpp"
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
        const BendingSpringResult<double> r =
            bending_spring(block.node_position(0, k), block.node_position(1, k),
                           block.node_position(2, k), rest, stiffness, plastic_set, yield);
        block.set_force(0, k, r.force_a);
        block.set_force(1, k, r.force_c);
        block.set_force(2, k, r.force_b);
        block.new_plastic_set[k] = r.plastic_set;
        block.dissipated[k] = r.dissipated;
      });
}

double bending_spring_energy(const Model& model, const State& state, SpringEnergy which) {
  return sum_over_intact(state.bend_broken, model.bend_count(), [&](Index s) {
    const Index* nodes = &model.bend_nodes[3 * s];
    const auto r = bending_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]],
                                  model.bend_rest_angle[s], model.bend_stiffness[s],
                                  plastic_set_of(state.bend_plastic_set, s),
                                  yield_limit(model.bend_yield_moment, s));
    return which == SpringEnergy::kWithFlow ? r.energy + r.dissipated : r.energy;
  });
}

const SpringKind kBendingSprings{
    .built = &kBendingSpringModel,
    .add_forces = add_bending_spring_forces,
    .energy = bending_spring_energy,
    .add_stiffness = add_bending_spring_stiffness,
    .report = &EnergyReport::bending,
    .plastic_set = &State::bend_plastic_set,
    .flow = &EnergyWorkspace::bend_flow,
    .broken = &State::bend_broken,
    .ns_per_item = measured::kNsPerBendingSpring,
    .ns_per_item_yielding = measured::kNsPerBendingSpringYielding,
    .constraint = {},
};

}  // namespace dinam
