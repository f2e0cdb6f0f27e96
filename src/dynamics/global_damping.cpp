#include "dynamics/global_damping.hpp"

#include "dynamics/force_kinds.hpp"
#include "dynamics/parallel_loops.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {

void add_global_damping_forces(ForceContext& context, double alpha) {
  const Model& model = context.model;
  if (alpha == 0.0) {
    return;
  }
  for_each_own_node(context.worker, model.node_count(), [&](Index i) {
    context.add(i, -(alpha * model.node_mass[i]) * context.state.velocity[i]);
  });
}

const ForceKind kGlobalDamping{
    .label = "global damping",
    .spring = nullptr,
    .role = ForceRole::kDissipation,
    .implicit = ImplicitTreatment::kDamper,
    .damper = {.mass_rate = [](const Model& model) { return model.global_damping; },
               .add_hessian = nullptr,
               .add_support_pull = nullptr},
    .switched = &ForceSwitches::global_damping,
    .present = nullptr,  // the settling phase may damp a model that has none
    .prepare_forces = nullptr,
    .add_forces =
        [](ForceContext& total, const StepOptions& options) {
          ForceContext booked = booked_in(total, &EnergyWorkspace::damping);
          add_global_damping_forces(booked,
                                    options.global_damping.value_or(total.model.global_damping));
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
          sink.add("global damping",
                   model.global_damping != 0.0 ? static_cast<double>(model.node_count()) : 0.0,
                   measured::kNsPerDampedNode);
        },
    .constraint = {},
};

}  // namespace dinam
