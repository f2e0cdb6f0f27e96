#include "solver/potential.hpp"

#include <cmath>

#include "dynamics/ground_contact.hpp"
#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {

Potential potential_energy(const Model& model, const State& state, const ForceSwitches& switches,
                           const std::vector<Vec3>& gravity_origin, SpringEnergy springs) {
  Potential potential;
  auto add = [&](double term) {
    potential.energy += term;
    potential.magnitude += std::abs(term);
  };
  for (const SpringKind* kind : kSpringKinds) {
    if (switches.*kind->switched) {
      add(kind->energy(model, state, springs));
    }
  }
  if (switches.gravity) {
    for (Index i = 0; i < model.node_count(); ++i) {
      if (!model.pinned(i)) {
        add(-model.node_mass[i] * model.gravity.dot(state.x[i] - gravity_origin[i]));
      }
    }
  }
  if (switches.ground) {
    add(ground_contact_energy(model, state));
  }
  return potential;
}

}  // namespace dinam
