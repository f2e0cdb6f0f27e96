#include "dynamics/clamp_spring.hpp"

#include <numbers>

#include "dynamics/bending_spring.hpp"
#include "dynamics/broken.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/parallel_loops.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

BendingSpringResult<double> clamp_spring(const Model& model, const State& state, Index s) {
  const Index c = model.clamp_nodes[2 * s];
  const Index a = model.clamp_nodes[2 * s + 1];
  const Vec3 ghost = state.x[c] + model.clamp_ghost_offset[s];
  return bending_spring(state.x[a], state.x[c], ghost, std::numbers::pi, model.clamp_stiffness[s],
                        plastic_set_of(state.clamp_plastic_set, s),
                        yield_limit(model.clamp_yield_moment, s));
}

}  // namespace

void add_clamp_forces(ForceContext& context) {
  const Model& model = context.model;
  State& state = context.state;
  EnergyWorkspace& ledger = state.energy_workspace;
  for (Index s = 0; s < model.clamp_count(); ++s) {
    const Index a = model.clamp_nodes[2 * s + 1];
    if (!context.worker.owns(a)) {
      continue;
    }
    if (is_broken(state.clamp_broken, s)) {
      if (context.update_history && ledger.enabled && model.clamps_yield) {
        ledger.clamp_flow[s] = 0.0;
      }
      continue;
    }
    const BendingSpringResult<double> r = clamp_spring(model, state, s);
    context.add(a, r.force_a);
    if (context.update_history && model.clamps_yield) {
      state.clamp_plastic_set[s] = r.plastic_set;
      if (ledger.enabled) {
        ledger.clamp_flow[s] = r.dissipated;
      }
    }
  }
}

double clamp_spring_energy(const Model& model, const State& state, SpringEnergy which) {
  return sum_over_intact(state.clamp_broken, model.clamp_count(), [&](Index s) {
    const auto r = clamp_spring(model, state, s);
    return which == SpringEnergy::kWithFlow ? r.energy + r.dissipated : r.energy;
  });
}

// A clamp is a bending spring, booked with them in the energy report.
void add_clamp_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  // Over (c, a); the ghost point moves with the support c, which is pinned, so only a's block
  // counts: the bending spring's over (a, c, g) at a.
  add_spring_stiffness<2>(model.clamp_count(), model.clamp_nodes, state.clamp_broken, state.x, sink,
                          [&](Index s, const std::array<Vec3, 2>& at) {
                            const LocalStiffness<3> bend = bending_spring_stiffness(
                                {at[1], at[0], at[0] + model.clamp_ghost_offset[s]},
                                std::numbers::pi, model.clamp_stiffness[s],
                                plastic_set_of(state.clamp_plastic_set, s),
                                yield_limit(model.clamp_yield_moment, s));
                            LocalStiffness<2> k = LocalStiffness<2>::Zero();
                            k.block<3, 3>(3, 3) = bend.block<3, 3>(0, 0);
                            return k;
                          });
}

const SpringKind kClampSprings{
    .built = &kClampModel,
    .add_forces = add_clamp_forces,
    .energy = clamp_spring_energy,
    .add_stiffness = add_clamp_stiffness,
    .report = &EnergyReport::bending,
    .plastic_set = &State::clamp_plastic_set,
    .flow = &EnergyWorkspace::clamp_flow,
    .broken = &State::clamp_broken,
    .ns_per_item = measured::kNsPerClampSpring,
    .ns_per_item_yielding = measured::kNsPerClampSpringYielding,
    .constraint = {},
};

}  // namespace dinam
