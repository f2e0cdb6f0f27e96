#pragma once
// Global viscous friction: −α m v on every node, from the velocities v_{n−½}, in the world frame
// (the paper's "atrito viscoso em relação ao sistema global").
#include "dynamics/force_context.hpp"

namespace dinam {

// −alpha m v (alpha in 1/s, the model's own or the settling phase's) on the context worker's own
// nodes (parallel_loops.hpp).
void add_global_damping_forces(ForceContext& context, double alpha);

}  // namespace dinam
