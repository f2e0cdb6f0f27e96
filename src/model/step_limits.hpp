#pragma once
// What sets the time step of a model, for `dinam info` and for the message that refuses a run too
// long to make: its shortest bars and the node whose springs vibrate fastest.
#include <string>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

struct BarLength {
  Index bar = 0;
  double length = 0.0;  // m, at rest
};

struct StepLimits {
  std::vector<BarLength> shortest;   // the shortest bars, shortest first
  double median_length = 0.0;        // m, over every bar
  Index fastest_node = -1;           // the free node with the highest row of the frequency bound
  double fastest_node_omega = 0.0;   // rad/s, its row's bound
  double shortest_at_fastest = 0.0;  // m, the shortest bar at that node
  bool contact_dominates = false;    // the node's row is mostly contact penalty
};

// The `count` shortest bars and the node that limits the step.
StepLimits find_step_limits(const Model& model, std::size_t count = 3);

// "object 'duck', node 12 at (0.1, 0.2, 0.3) m", for messages.
std::string describe_node(const Model& model, Index node);

}  // namespace dinam
