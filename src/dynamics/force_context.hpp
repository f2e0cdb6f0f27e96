#pragma once
// What every force loop receives: the model, the state it reads (and, for plastic sets and
// contact anchors, updates), and where to add its forces.
#include <vector>

#include "dynamics/state.hpp"
#include "model/spring_colouring.hpp"

namespace dinam {

struct Model;

struct ForceContext {
  const Model& model;
  State& state;
  std::vector<Vec3>& force;  // (n_nodes) N, the total, added to
  // False while probing forces without advancing (finite differences, energy reports): plastic
  // sets and contact anchors are then read but not written.
  bool update_history = true;
  // While the energy is tracked, a dissipative or driving kind (fields, wind, dampers) also adds
  // its forces to its own array here, whose work the report books; null otherwise. The total is
  // summed in the same order either way, so tracking cannot change a bit of the motion.
  std::vector<Vec3>* ledger = nullptr;

  // Adds f to the node's total force and, while tracked, to the kind's ledger.
  void add(Index node, const Vec3& f) {
    force[node] += f;
    if (ledger != nullptr) {
      (*ledger)[node] += f;
    }
  }

  // The work that the plastic flow of one block of springs dissipated in this evaluation (J),
  // kept only when the context advances history. Safe from parallel loops: each block writes its
  // own slot.
  void record_plastic_flow(Index block, double dissipated) {
    if (update_history) {
      state.plastic_flow[static_cast<std::size_t>(block)] = dissipated;
    }
  }

  // After a loop over the springs of one kind: books the dissipation of their flow, summed block
  // by block in spring order, so that the total does not depend on the threads. Nothing to do
  // for a kind that cannot yield.
  void book_plastic_flow(const SpringColouring& springs) {
    if (update_history && springs.any_yield) {
      const Index blocks = (springs.spring_count + kSpringBlockSize - 1) / kSpringBlockSize;
      for (Index b = 0; b < blocks; ++b) {
        state.energy.plastic_dissipation += state.plastic_flow[static_cast<std::size_t>(b)];
      }
    }
  }
};

}  // namespace dinam
