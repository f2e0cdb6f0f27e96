#include "solver/potential.hpp"

#include "dynamics/force_kinds.hpp"
#include "model/model.hpp"

namespace dinam {

Potential potential_energy(const Model& model, const State& state, const ForceSwitches& switches,
                           const std::vector<Vec3>& gravity_origin, SpringEnergy springs) {
  Potential potential;
  const PotentialQuery query{gravity_origin, springs};
  for (const ForceKind* kind : kForceKinds) {
    if (kind->add_potential != nullptr && switches.*kind->switched) {
      kind->add_potential(model, state, query, potential);
    }
  }
  return potential;
}

}  // namespace dinam
