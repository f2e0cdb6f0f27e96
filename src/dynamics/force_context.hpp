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

  // An elastoplastic spring's new plastic set and the work its flow dissipated, kept only when
  // the context advances history.
  void record_plastic_flow(double& plastic_set, double new_plastic_set, double dissipated) {
    if (update_history) {
      plastic_set = new_plastic_set;
      state.energy.plastic_dissipation += dissipated;
    }
  }
};

}  // namespace dinam
