#include "dynamics/field_forces.hpp"

#include "dynamics/parallel_loops.hpp"
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
    const Vec3 value = field.profile(context.state.time) * field.value;
    for (const Index i : field.nodes) {
      if (context.worker.owns(i)) {
        context.add(i, field.per_unit_mass ? Vec3(model.node_mass[i] * value) : value);
      }
    }
  }
}

}  // namespace dinam
