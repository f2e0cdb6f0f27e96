#include "dynamics/step_cost.hpp"

#include <algorithm>

#include "dynamics/integrator.hpp"
#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Nanoseconds per item on one thread, from `build/bench/bench_force_costs` (the large flag and
// its lattice, about 100 000 of each kind; bench/notes/performance.md, "Every force kind against the
// springs"). Measure again and update them when a kernel changes: nothing else depends on them
// but the estimates that `info` prints and `render` and `simulate` refuse long runs on.
// The springs' costs are their kinds' (spring_kind.hpp).
struct ItemCosts {
  double damper = 5.3;          // a bar's axial damper
  double node = 5.4;            // gravity, clearing and the integrator, per node
  double global_damping = 1.3;  // per node
  double field_node = 0.8;      // per node a field acts on
  double ground = 9.2;          // per node, half of them touching
  double wind_face = 15.1;      // a face in steady or gusty wind
  double wind_face_turbulent = 25.3;
  double wind_bar = 10.1;  // a bare bar in the wind
  double wind_bar_turbulent = 17.6;
  double contact_primitive = 30.0;  // a bar or node watched for contact between objects
  double tearing_bar = 1.0;         // a bar checked against its breaking limit
};
constexpr ItemCosts kCosts;

// A step on two idle threads against one, as bench_threads measures on 5 000 to 50 000 bars:
// each thread past the first adds this fraction of one.
constexpr double kThreadEfficiency = 0.8;

}  // namespace

StepCost estimate_step_cost(const Model& model, int threads) {
  StepCost cost;
  auto add = [&](const char* kind, double items, double ns_each) {
    if (items > 0) {
      cost.parts.push_back({kind, items, items * ns_each});
      cost.serial_ns += items * ns_each;
    }
  };
  const double nodes = static_cast<double>(model.node_count());
  for (const SpringKind* kind : kSpringKinds) {
    add(kind->name(), static_cast<double>(kind->count(model)),
        kind->yields(model) ? kind->ns_per_item_yielding : kind->ns_per_item);
  }
  add("axial dampers", model.any_bar_damping ? static_cast<double>(model.bar_count()) : 0.0,
      kCosts.damper);
  add("nodes and integrator", nodes, kCosts.node);
  add("global damping", model.global_damping != 0.0 ? nodes : 0.0, kCosts.global_damping);
  double field_nodes = 0.0;
  for (const FieldForce& field : model.fields) {
    field_nodes += static_cast<double>(field.nodes.size());
  }
  add("fields", field_nodes, kCosts.field_node);
  add("ground", model.ground.enabled ? nodes : 0.0, kCosts.ground);
  if (model.wind.field.enabled) {
    const bool turbulent = model.wind.field.turbulence != 0.0;
    add("wind on faces", static_cast<double>(model.wind.faces.size()),
        turbulent ? kCosts.wind_face_turbulent : kCosts.wind_face);
    add("wind on bars", static_cast<double>(model.wind.bars.size()),
        turbulent ? kCosts.wind_bar_turbulent : kCosts.wind_bar);
  }
  if (model.contact.enabled) {
    add("contact between objects",
        static_cast<double>(model.contact.bars.size() + model.contact.points.size()),
        kCosts.contact_primitive);
  }
  add("tearing", model.can_tear() ? static_cast<double>(model.bar_count()) : 0.0,
      kCosts.tearing_bar);

  cost.threads = threads > 1 && worth_sharing(model) ? threads : 1;
  const double speedup = 1.0 + kThreadEfficiency * (cost.threads - 1);
  cost.seconds = 1e-9 * cost.serial_ns / speedup;
  return cost;
}

}  // namespace dinam
