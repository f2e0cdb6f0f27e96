#include "estimate/step_cost.hpp"

#include "dynamics/force_kinds.hpp"
#include "dynamics/integrator.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {

StepCost estimate_step_cost(const Model& model, int threads, bool as_xpbd) {
  StepCost cost;
  StepCostSink sink(cost);
  for (const ForceKind* kind : kForceKinds) {
    const bool held = kind->held_as_constraint(model) || (as_xpbd && kind->constraint.held);
    if (held) {
      if (kind->constraint.add_cost != nullptr) {
        kind->constraint.add_cost(model, sink);
      }
    } else if (kind->add_cost != nullptr) {
      kind->add_cost(model, sink);
    }
  }
  sink.add("nodes and integrator", static_cast<double>(model.node_count()), measured::kNsPerNode);
  sink.add("tearing", model.can_tear() ? static_cast<double>(model.bar_count()) : 0.0,
           measured::kNsPerTearingBar);

  cost.threads = threads > 1 && worth_sharing(model) ? threads : 1;
  const double speedup = 1.0 + measured::kThreadEfficiency * (cost.threads - 1);
  cost.seconds = 1e-9 * ((cost.serial_ns - cost.unshared_ns) / speedup + cost.unshared_ns);
  return cost;
}

}  // namespace dinam
