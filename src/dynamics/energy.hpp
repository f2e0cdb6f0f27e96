#pragma once
// Energy of a configuration, for tests and the CSV report.
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

double kinetic_energy(const Model& model, const std::vector<Vec3>& v);        // Σ ½ m |v|², J
double gravitational_energy(const Model& model, const std::vector<Vec3>& x);  // Σ −m g·x, J

// The full report at the state's positions, with the given whole-step velocities.
EnergyReport energy_report(const Model& model, const State& state,
                           const std::vector<Vec3>& v_whole);

}  // namespace dinam
