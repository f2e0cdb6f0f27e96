#pragma once
// The ground's restitution inside the implicit integrator. Its steps are far longer than an
// impact (the automatic ground lasts a third of a step, π/ω_c with ω_c h = 10), and backward
// Euler's step into the penalty ends with the node at rest on the plane, whatever the damper
// would have given back: an impact was inelastic, and a rubber body that central differences
// bounce (the Wuson's loose bits scattered) lay where it fell. So, after the step, each node that
// landed within it leaves with the normal velocity the ground's spring and damper send a mass
// back with, e(ζ) times the speed it struck at: the clipped spring–dashpot's closed form (its
// force only pushes, so the contact ends when k x + c ẋ = 0 with the mass still moving),
//   e(ζ) = exp(−ζ φ / √(1 − ζ²)) |cos φ − ζ/√(1 − ζ²) sin φ|,
//   φ = π − atan2(2ζ√(1 − ζ²), 1 − 2ζ²),
// ζ = c / (2 √(k m)) the node's damping ratio on the ground (0 rebound from ζ = 1 on). The speed
// it struck at is that of a free fall from x_n under gravity, √(u_n² + 2 g⊥ d) for a node d
// above the plane moving along its normal at u_n: exact for a node alone, and for a structure the
// speed its landing node had before the springs around it felt the ground.
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// The clipped spring–dashpot's restitution at damping ratio ζ ≥ 0.
double spring_dashpot_restitution(double zeta);

// After an implicit step from (x_start, v_start) to state (positions and velocities v_{n+1} in
// state.velocity): every free node above the plane at x_start and on it at state.x leaves with e(ζ)
// times the speed it struck at along the normal, where it would leave slower. True where any did.
bool rebound_landing_nodes(const Model& model, const std::vector<Vec3>& x_start,
                           const std::vector<Vec3>& v_start, State& state);

}  // namespace dinam
