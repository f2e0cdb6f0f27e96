#pragma once
// The total potential energy that Newton's method minimises: what the forces of a static problem
// derive from.
#include "dynamics/force_kind.hpp"
#include "dynamics/force_switches.hpp"
#include "dynamics/spring_kind.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// At state.x, with the plastic sets and broken springs as the state holds them, from every
// spring kind `switches` leaves on, gravity and the ground's normal penalty (not friction, whose
// anchor is history, nor fields, wind or dampers). Gravity's share is measured from
// `gravity_origin` (n_nodes), the positions where it is zero, so that it holds no large constant
// to round; pinned nodes' share, constant, is left out.
// `springs`: the springs' stored energy, or that and their flow's work from the state's plastic
// sets (spring_kind.hpp), for a minimisation that holds the plastic sets while springs may flow.
Potential potential_energy(const Model& model, const State& state, const ForceSwitches& switches,
                           const std::vector<Vec3>& gravity_origin,
                           SpringEnergy springs = SpringEnergy::kStored);

}  // namespace dinam
