#include "dynamics/torsion_spring.hpp"

#include "dynamics/broken.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/spring_block.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {

void add_torsion_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  const SpringArrays springs{model.torsion_count(),
                             model.torsions_yield,
                             &MemberShare::torsions,
                             model.torsion_nodes,
                             model.torsion_rest_angle,
                             model.torsion_stiffness,
                             model.torsion_yield_moment,
                             context.state.torsion_plastic_set,
                             broken_flags(context.state.torsion_broken),
                             flow_record(context, context.state.energy_workspace.torsion_flow)};
  add_spring_forces<4>(
      context, springs,
      [](SpringBlock<4> & block, Index k, double rest, double stiffness, double plastic_set,
         double yield) __attribute__((always_inline)) {
        const TorsionSpringResult<double> r = torsion_spring(
            block.node_position(0, k), block.node_position(1, k), block.node_position(2, k),
            block.node_position(3, k), rest, stiffness, plastic_set, yield);
        block.set_force(0, k, r.force_a);
        block.set_force(1, k, r.force_i);
        block.set_force(2, k, r.force_j);
        block.set_force(3, k, r.force_b);
        block.new_plastic_set[k] = r.plastic_set;
        block.dissipated[k] = r.dissipated;
      });
}

double torsion_spring_energy(const Model& model, const State& state, SpringEnergy which) {
  return sum_over_intact(state.torsion_broken, model.torsion_count(), [&](Index s) {
    const Index* nodes = &model.torsion_nodes[4 * s];
    const auto r = torsion_spring(
        state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]], state.x[nodes[3]],
        model.torsion_rest_angle[s], model.torsion_stiffness[s],
        plastic_set_of(state.torsion_plastic_set, s), yield_limit(model.torsion_yield_moment, s));
    return which == SpringEnergy::kWithFlow ? r.energy + r.dissipated : r.energy;
  });
}

const SpringKind kTorsionSprings{
    .built = &kTorsionSpringModel,
    .add_forces = add_torsion_spring_forces,
    .energy = torsion_spring_energy,
    .add_stiffness = add_torsion_spring_stiffness,
    .report = &EnergyReport::torsion,
    .plastic_set = &State::torsion_plastic_set,
    .flow = &EnergyWorkspace::torsion_flow,
    .broken = &State::torsion_broken,
    .ns_per_item = measured::kNsPerTorsionSpring,
    .ns_per_item_yielding = measured::kNsPerTorsionSpringYielding,
    .constraint = {},
};

}  // namespace dinam
