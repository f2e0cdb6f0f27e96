#pragma once
// Clamps (model.hpp): at a clamped pinned node c, a bending spring between the bar c–a and the
// fixed ghost point g = x_c + (c₀ − a₀), rest angle π, so that the bar keeps its rest direction
// there. The support takes the shares of c and g; a feels the rest.
#include "dynamics/force_context.hpp"
#include "dynamics/spring_kind.hpp"

namespace dinam {

struct Model;

// A few springs at the supports: one loop in clamp order, each worker the clamps of its own free
// nodes.
void add_clamp_forces(ForceContext& context);
double clamp_spring_energy(const Model& model, const State& state, SpringEnergy which);
// Over the support c and the free node a; the support's share (its row) goes to the support.
void add_clamp_stiffness(const Model& model, const State& state, StiffnessSink& sink);

// The entry of spring_kinds.hpp.
extern const SpringKind kClampSprings;

}  // namespace dinam
