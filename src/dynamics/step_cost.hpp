#pragma once
// What a step of a model costs, estimated from what it holds (springs of each kind, nodes, faces
// in the wind, contact primitives) and a cost per item of each force kind, measured once by the
// benchmark (bench/force_costs.cpp, one thread) and kept here. The estimate does not depend on
// how busy the machine is now, so the same scene gets the same answer on a quiet machine and on
// a shared one (a test or a refusal can rest on it); it is the time on a machine like the one the
// costs were measured on (bench/notes/performance.md), which a faster or slower machine scales.
#include <string>
#include <vector>

namespace dinam {

struct Model;

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

// The cost of a step of `model` on `threads` threads. The spring, node and drag loops are split
// between the threads where the model is large enough for that to pay (the step's own rule), at
// the efficiency bench_threads measures on two idle cores; contact between objects is counted at
// the cost of watching for it, a surface with contact with itself (a cloth that folds) at what a
// cloth lying on itself costs.
// With `as_xpbd`, the step of `integrator: xpbd` whatever the model's own integrator: the kinds it
// holds as constraints cost their projection's sweeps, on one thread, not their forces.
StepCost estimate_step_cost(const Model& model, int threads, bool as_xpbd = false);

}  // namespace dinam
