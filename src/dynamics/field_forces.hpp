#pragma once
// Field forces: gravity m g on every node, and the scene's fields (per unit mass or per node,
// scaled by their time profile).
#include "dynamics/force_context.hpp"

namespace dinam {

// Each on the context worker's own nodes (parallel_loops.hpp).
void add_gravity_forces(ForceContext& context);
void add_field_forces(ForceContext& context);  // at the context's time

}  // namespace dinam
