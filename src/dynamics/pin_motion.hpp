#pragma once
// Shaken supports: pinned nodes that follow a prescribed path (PinMotion) instead of staying put.
// They keep zero inverse mass, so no force moves them; their half-step velocity is set to the
// path's secant, which carries them along it through the ordinary position update and lets
// dampers, drag and the ground see how fast they move.
#include <functional>

#include "dynamics/state.hpp"

namespace dinam {

struct Model;
struct PinMotion;

// Where the `k`th node of `motion` is at time t: on its path, or on its track (linear between
// samples, at the first before t = 0 and the last after the track ends).
Vec3 driven_position(const Model& model, const PinMotion& motion, std::size_t k, double t);

// Where the driven nodes are at time t.
void place_driven_nodes(const Model& model, double t, State& state);

// v_{n+½} of every driven node into `v_half`, so that x_{n+1} = x_n + Δt v_{n+½} lands on the
// path at t_{n+1}, from the positions x_n; with `owns`, only of the nodes for which it is true (a
// worker's own, parallel_loops.hpp).
void set_driven_velocities(const Model& model, double t_next, double dt, const std::vector<Vec3>& x,
                           std::vector<Vec3>& v_half, const std::function<bool(Index)>& owns = {});

}  // namespace dinam
