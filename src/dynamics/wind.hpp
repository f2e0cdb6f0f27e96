#pragma once
// Aerodynamic drag from a wind velocity field: pressure drag on mesh faces from the normal
// component of the relative velocity, and cross-flow drag on bare bars.
#include "core/types.hpp"
#include "dynamics/force_context.hpp"

namespace dinam {

struct WindDesc;

// The wind velocity at a point and time, m/s: the mean, plus gusts along the mean direction
// (a sine of the gust period), plus smooth seeded turbulence — a sum of a few travelling waves
// per component, of wavelengths around the turbulence scale, carried along by the mean wind.
Vec3 wind_velocity(const WindDesc& wind, const Vec3& x, double t);

// Drag on a face of area vector s = A n (|s| = A) moving with velocity v in wind w:
// F = ½ ρ Cd A (v_rel·n) |v_rel·n| n, v_rel = w − v. Only the normal flow pushes a thin sheet.
Vec3 face_drag(const Vec3& area_vector, const Vec3& relative_velocity, double air_density,
               double drag_coefficient);

// Cross-flow drag on a cylinder of diameter D and length L along unit t:
// F = ½ ρ Cd D L |v⊥| v⊥, v⊥ = v_rel − (v_rel·t) t.
Vec3 bar_drag(const Vec3& axis, double diameter, const Vec3& relative_velocity, double air_density,
              double drag_coefficient);

void add_wind_forces(ForceContext& context);

}  // namespace dinam
