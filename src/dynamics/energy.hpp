#pragma once
// Energy of a configuration, for tests and reports. The leapfrog velocity at a whole step is the
// mean of the two half steps around it; pass that to kinetic_energy.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

double kinetic_energy(const Model& model, const std::vector<Vec3>& v);        // Σ ½ m |v|², J
double gravitational_energy(const Model& model, const std::vector<Vec3>& x);  // Σ −m g·x, J

}  // namespace dinam
