#pragma once
// What every force loop receives: the model, the state it reads (and, for plastic sets and
// contact anchors, updates), where to add its forces, and which part of the work is its own.
#include <vector>

#include "dynamics/parallel_loops.hpp"
#include "dynamics/state.hpp"

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
  // The thread running this part of the loops and what is its own (parallel_loops.hpp); by
  // default one thread that does everything.
  Worker worker;
  // s, the instant the forces are taken at: the state's time in a step; the implicit step takes
  // the fields at the step's end without moving the state's clock.
  double time = 0.0;

  // Keeps `value` aside to write to `slot` once the team has met (spring_block.hpp).
  void put_aside(double* slot, double value) {
    state.plastic_set_updates[static_cast<std::size_t>(worker.member.index())].push_back(
        {slot, value});
  }

  // Adds f to the node's total force and, while tracked, to the kind's ledger.
  void add(Index node, const Vec3& f) {
    force[node] += f;
    if (ledger != nullptr) {
      (*ledger)[node] += f;
    }
  }
};

// A kind's own array in `part` of the energy ledger while the energy is tracked; else null.
inline std::vector<Vec3>* ledger_part(State& state, std::vector<Vec3> EnergyWorkspace::*part) {
  EnergyWorkspace& ledger = state.energy_workspace;
  return ledger.enabled ? &(ledger.*part) : nullptr;
}

// The context of a kind that keeps its own forces in `part` of the energy ledger while the energy
// is tracked: the same total, booked there too.
inline ForceContext booked_in(const ForceContext& total, std::vector<Vec3> EnergyWorkspace::*part) {
  return {
      total.model,  total.state, total.force, total.update_history, ledger_part(total.state, part),
      total.worker, total.time};
}

}  // namespace dinam
