#pragma once
// What every force loop receives: the model, the state it reads (and, for plastic sets and
// contact anchors, updates), and where to add its forces.
#include <vector>

#include "dynamics/state.hpp"

namespace dinam {

struct Model;

struct ForceContext {
  const Model& model;
  State& state;
  std::vector<Vec3>& force;  // (n_nodes) N, added to
  // False while probing forces without advancing (finite differences, energy reports): plastic
  // sets and contact anchors are then read but not written.
  bool update_history = true;
};

}  // namespace dinam
