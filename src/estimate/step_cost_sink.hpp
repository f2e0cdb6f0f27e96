#pragma once
// What a step's estimate is made of, and the sink each force kind adds its share into
// (dynamics/force_kind.hpp's add_cost: the items it loops over, at their measured cost from
// measured_costs.hpp). Header-only, with no dependency, so that the force kinds below the
// estimates can fill it; estimate_step_cost (step_cost.hpp) sums it.
#include <string>
#include <vector>

namespace dinam {

// One force kind's share of a step.
struct StepCostPart {
  std::string kind;  // "torsion springs", "integrator", …
  double items = 0;  // springs, nodes, faces … that the kind loops over
  double ns = 0.0;   // a step's time for them on one thread, ns
};

struct StepCost {
  std::vector<StepCostPart> parts;
  double serial_ns = 0.0;    // Σ parts: one thread
  double unshared_ns = 0.0;  // of it, what more threads do not shorten
  int threads = 1;           // the threads it was scaled to (1 where the model is too small)
  double seconds = 0.0;      // a step on `threads` threads, s
};

// Where each force kind adds its share (force_kind.hpp): `items` it loops over, at `ns_each` on one
// thread; a kind with none adds nothing.
class StepCostSink {
 public:
  explicit StepCostSink(StepCost& cost) : cost_(cost) {}
  void add(const char* kind, double items, double ns_each) {
    if (items > 0) {
      cost_.parts.push_back({kind, items, items * ns_each});
      cost_.serial_ns += items * ns_each;
    }
  }
  // The same for work that more threads do not shorten.
  void add_unshared(const char* kind, double items, double ns_each) {
    add(kind, items, ns_each);
    cost_.unshared_ns += items * ns_each;
  }

 private:
  StepCost& cost_;
};

}  // namespace dinam
