#include "dynamics/global_damping.hpp"

#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {

void add_global_damping_forces(ForceContext& context, double alpha) {
  const Model& model = context.model;
  if (alpha == 0.0) {
    return;
  }
  for_each_own_node(context.worker, model.node_count(), [&](Index i) {
    context.add(i, -(alpha * model.node_mass[i]) * context.state.v_half[i]);
  });
}

}  // namespace dinam
