#pragma once
// Aerodynamic drag from the wind velocity field (wind_field.hpp): pressure drag on mesh faces
// from the normal component of the relative velocity, and cross-flow drag on bare bars.
#include <cmath>

#include "core/geometry.hpp"
#include "core/types.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

// Drag on a face of area vector s = A n (|s| = A) moving with velocity v in wind w:
// F = ½ ρ Cd A (v_rel·n) |v_rel·n| n, v_rel = w − v. Only the normal flow pushes a thin sheet.
// A face of no area takes none (n is then 0 too). No branches, and dot3 rather than Eigen's dot:
// the loop over faces vectorises.
[[gnu::always_inline]] inline Vec3 face_drag(const Vec3& area_vector, const Vec3& relative_velocity,
                                             double air_density, double drag_coefficient) {
  const double area = norm3(area_vector);
  const Vec3 normal = (1.0 / (area > 0.0 ? area : 1.0)) * area_vector;  // one division, not three
  const double normal_speed = dot3(relative_velocity, normal);
  return (0.5 * air_density * drag_coefficient * area * normal_speed * std::abs(normal_speed)) *
         normal;
}

// Cross-flow drag on a cylinder of diameter D and length L along unit t:
// F = ½ ρ Cd D L |v⊥| v⊥, v⊥ = v_rel − (v_rel·t) t. A bar of no length takes none.
[[gnu::always_inline]] inline Vec3 bar_drag(const Vec3& axis, double diameter,
                                            const Vec3& relative_velocity, double air_density,
                                            double drag_coefficient) {
  const double length = norm3(axis);
  const Vec3 t = (1.0 / (length > 0.0 ? length : 1.0)) * axis;
  const Vec3 cross_flow = relative_velocity - dot3(relative_velocity, t) * t;
  return (0.5 * air_density * drag_coefficient * diameter * length * norm3(cross_flow)) *
         cross_flow;
}

// Sizes the wind's scratch in the state (State::wind) for the model.
void prepare_wind(const Model& model, State& state);

// The drag on every face and bare bar in the wind, into the state's wind scratch, each to be
// shared equally by its nodes. A face feels the mean of its nodes' velocities and of the wind at
// its nodes; a bar the same of its two ends. The context's team shares the nodes (when turbulent),
// then the faces and bars, and meets at a barrier after each.
void compute_wind_drag(ForceContext& context);

// Adds the drag that compute_wind_drag found to the context worker's own nodes
// (parallel_loops.hpp), each node its items' in a fixed order: the result does not depend on the
// threads.
void add_wind_forces(ForceContext& context);

}  // namespace dinam
