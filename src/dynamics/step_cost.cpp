#include "dynamics/step_cost.hpp"

#include "dynamics/force_kinds.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Nanoseconds per item on one thread, from `build/bench/bench_force_costs` (the large flag and
// its lattice, about 100 000 of each kind; bench/notes/performance.md, "Every force kind against
// the springs"), for the work that belongs to no force kind; each kind's own cost is in its entry
// (force_kind.hpp). Measure again and update them when a kernel changes: nothing else depends on
// them but the estimates that `info` prints and `render` and `simulate` refuse long runs on.
constexpr double kNodeNs = 5.4;        // gravity, clearing and the integrator, per node
constexpr double kTearingBarNs = 1.0;  // a bar checked against its breaking limit

// A step on two idle threads against one, as bench_threads measures on 5 000 to 50 000 bars:
// each thread past the first adds this fraction of one.
constexpr double kThreadEfficiency = 0.8;

}  // namespace

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
  sink.add("nodes and integrator", static_cast<double>(model.node_count()), kNodeNs);
  sink.add("tearing", model.can_tear() ? static_cast<double>(model.bar_count()) : 0.0,
           kTearingBarNs);

  cost.threads = threads > 1 && worth_sharing(model) ? threads : 1;
  const double speedup = 1.0 + kThreadEfficiency * (cost.threads - 1);
  cost.seconds = 1e-9 * ((cost.serial_ns - cost.unshared_ns) / speedup + cost.unshared_ns);
  return cost;
}

}  // namespace dinam
