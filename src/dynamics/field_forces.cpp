#include "dynamics/field_forces.hpp"

#include "dynamics/energy.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/parallel_loops.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {

void add_gravity_forces(ForceContext& context) {
  const Model& model = context.model;
  for_each_own_node(context.worker, model.node_count(),
                    [&](Index i) { context.force[i] += model.node_mass[i] * model.gravity; });
}

void add_field_forces(ForceContext& context) {
  const Model& model = context.model;
  for (const FieldForce& field : model.fields) {
    const Vec3 value = field.profile(context.time) * field.value;
    for (const Index i : field.nodes) {
      if (context.worker.owns(i)) {
        context.add(i, field.per_unit_mass ? Vec3(model.node_mass[i] * value) : value);
      }
    }
  }
}

// Gravity: a potential, −Σ m g·x; its cost is in the nodes' own (estimate/step_cost.cpp).
const ForceKind kGravity{
    .label = "gravity",
    .spring = nullptr,
    .role = ForceRole::kPotential,
    .implicit = ImplicitTreatment::kInPotential,
    .damper = {},
    .switched = &ForceSwitches::gravity,
    .present = nullptr,
    .prepare_forces = nullptr,
    .add_forces = [](ForceContext& total, const StepOptions&) { add_gravity_forces(total); },
    .add_forces_after_team = nullptr,
    // Measured from the query's origin, over the free nodes: pinned nodes' share is constant.
    .add_potential =
        [](const Model& model, const State& state, const PotentialQuery& query,
           Potential& potential) {
          for (Index i = 0; i < model.node_count(); ++i) {
            if (!model.pinned(i)) {
              potential.add(-model.node_mass[i] *
                            model.gravity.dot(state.x[i] - query.gravity_origin[i]));
            }
          }
        },
    .add_stiffness = nullptr,
    .report_energy =
        [](const Model& model, const State& state, EnergyReport& report) {
          report.gravitational += gravitational_energy(model, state.x);
        },
    .ledger = {},
    .prepare_state = nullptr,
    .state_bytes = nullptr,
    .add_cost = nullptr,
    .constraint = {},
};

// The scene's fields: loads of the time alone.
const ForceKind kFields{
    .label = "fields",
    .spring = nullptr,
    .role = ForceRole::kLoad,
    .implicit = ImplicitTreatment::kLoadAtEnd,
    .damper = {},
    .switched = &ForceSwitches::fields,
    .present = [](const Model& model) { return !model.fields.empty(); },
    .prepare_forces = nullptr,
    .add_forces =
        [](ForceContext& total, const StepOptions&) {
          ForceContext booked = booked_in(total, &EnergyWorkspace::field);
          add_field_forces(booked);
        },
    .add_forces_after_team = nullptr,
    .add_potential = nullptr,
    .add_stiffness = nullptr,
    .report_energy = nullptr,
    .ledger = {{&EnergyWorkspace::field, &EnergyAccounts::field_work}},
    .prepare_state = nullptr,
    .state_bytes = nullptr,
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          double nodes = 0.0;
          for (const FieldForce& field : model.fields) {
            nodes += static_cast<double>(field.nodes.size());
          }
          sink.add("fields", nodes, measured::kNsPerFieldNode);
        },
    .constraint = {},
};

}  // namespace dinam
