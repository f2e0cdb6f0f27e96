#pragma once
// Field forces: gravity, m g on every node.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

void add_gravity_forces(const Model& model, std::vector<Vec3>& force);

}  // namespace dinam
