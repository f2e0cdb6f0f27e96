#include "dynamics/axial_spring.hpp"

#include "dynamics/axial_damper_implicit.hpp"
#include "dynamics/bar_constraints.hpp"

#include "dynamics/broken.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/spring_block.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {

void add_axial_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  const SpringArrays springs{model.bar_count(),
                             model.bars_yield,
                             &MemberShare::bars,
                             model.bar_nodes,
                             model.bar_rest_length,
                             model.bar_axial_stiffness,
                             model.bar_yield_force,
                             context.state.bar_plastic_set,
                             broken_flags(context.state.bar_broken),
                             flow_record(context, context.state.energy_workspace.bar_flow)};
  add_spring_forces<2>(
      context, springs,
      [](SpringBlock<2> & block, Index k, double rest, double stiffness, double plastic_set,
         double yield) __attribute__((always_inline)) {
        const AxialSpringResult<double> r =
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
  const Worker& worker = context.worker;
  for_each_spring_chunk(worker, &MemberShare::bars, model.bar_count(), kSpringBlockSize,
                        [&](Index first, Index count) {
                          for (Index b = first; b < first + count; ++b) {
                            if (model.bar_damping[b] == 0.0 || is_broken(state.bar_broken, b)) {
                              continue;
                            }
                            const Index n0 = model.bar_nodes[2 * b];
                            const Index n1 = model.bar_nodes[2 * b + 1];
                            const Vec3 f0 =
                                axial_damper(state.x[n0], state.x[n1], state.velocity[n0],
                                             state.velocity[n1], model.bar_damping[b]);
                            if (worker.owns(n0)) {
                              context.add(n0, f0);
                            }
                            if (worker.owns(n1)) {
                              context.add(n1, -f0);
                            }
                          }
                        });
}

double axial_spring_energy(const Model& model, const State& state, SpringEnergy which) {
  if (which == SpringEnergy::kStored && model.bars_are_constraints()) {
    // Held as constraints, the paper's rigid bars: they store nothing. Their length's share
    // beyond the rest is what the sweeps leave unsolved, no spring's; the work their projection
    // does is booked as numerical dissipation (integrator.cpp).
    return 0.0;
  }
  return sum_over_intact(state.bar_broken, model.bar_count(), [&](Index b) {
    const auto r = axial_spring(
        state.x[model.bar_nodes[2 * b]], state.x[model.bar_nodes[2 * b + 1]],
        model.bar_rest_length[b], model.bar_axial_stiffness[b],
        plastic_set_of(state.bar_plastic_set, b), yield_limit(model.bar_yield_force, b));
    return which == SpringEnergy::kWithFlow ? r.energy + r.dissipated : r.energy;
  });
}

const SpringKind kAxialSprings{
    .built = &kAxialSpringModel,
    .add_forces = add_axial_spring_forces,
    .energy = axial_spring_energy,
    .add_stiffness = add_axial_spring_stiffness,
    .report = &EnergyReport::axial,
    .plastic_set = &State::bar_plastic_set,
    .flow = &EnergyWorkspace::bar_flow,
    .broken = &State::bar_broken,
    .ns_per_item = measured::kNsPerAxialSpring,
    .ns_per_item_yielding = measured::kNsPerAxialSpringYielding,
    .constraint = {.held = true,
                   .project = project_bars,
                   .finish = flow_bars,
                   .add_cost =
                       [](const Model& model, StepCostSink& sink) {
                         sink.add_unshared(
                             "the bars' projection",
                             kConstraintSweeps * static_cast<double>(model.bar_count()),
                             measured::kNsPerBarProjection);
                       }},
};

// The bars' axial dampers, along each bar.
const ForceKind kAxialDampers{
    .label = "axial dampers",
    .spring = nullptr,
    .role = ForceRole::kDissipation,
    .implicit = ImplicitTreatment::kDamper,
    .damper = {.mass_rate = nullptr,
               .add_hessian = add_axial_damper_hessian,
               .add_support_pull = add_axial_damper_support_pull},
    .switched = &ForceSwitches::axial_dampers,
    .present = [](const Model& model) { return model.any_bar_damping; },
    .prepare_forces = nullptr,
    .add_forces =
        [](ForceContext& total, const StepOptions&) {
          ForceContext booked = booked_in(total, &EnergyWorkspace::damping);
          add_axial_damper_forces(booked);
        },
    .add_forces_after_team = nullptr,
    .add_potential = nullptr,
    .add_stiffness = nullptr,
    .report_energy = nullptr,
    .ledger = {{&EnergyWorkspace::damping, &EnergyAccounts::damping_work}},
    .prepare_state = nullptr,
    .state_bytes = nullptr,
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          sink.add("axial dampers",
                   model.any_bar_damping ? static_cast<double>(model.bar_count()) : 0.0,
                   measured::kNsPerDamper);
        },
    .constraint = {.held = true,
                   .project = nullptr,  // the bars' projection takes their dampers in
                   .finish = nullptr,
                   .add_cost = nullptr},
};

}  // namespace dinam
