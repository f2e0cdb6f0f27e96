#pragma once
// The order in which the projection of the bars held as constraints (`integrator: xpbd`,
// dynamics/bar_constraints.hpp) sweeps them: by colour, no two bars of a colour sharing a node
// (a greedy colouring in bar order, each bar taking the first colour free at both its nodes), so
// that each projection of a colour need not wait for the one before it. In bar order a cloth's
// bars draw a chain through shared nodes, and the sweep took a third longer.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

// Every bar once, colour by colour, each colour's bars in increasing order; a bar at a node of
// more than 64 bars comes after every colour.
std::vector<Index> bar_sweep_order(const Model& model);

}  // namespace dinam
