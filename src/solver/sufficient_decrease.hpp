#pragma once
// When a step of Newton's method on an energy is taken, for the equilibrium's line search
// (equilibrium.hpp) and the implicit integrator's trust region (implicit_newton.hpp).

namespace dinam {

// A step is taken once the energy falls by at least this share of what the quadratic model of the
// energy promised (any decrease that is not vanishing).
inline constexpr double kSufficientDecrease = 1e-4;
// Energies nearer than this share of the energy's magnitude are equal within rounding (a few
// hundred ulps of the sum): near a minimum every step changes the energy by less, and the step is
// judged by the out-of-balance force instead.
inline constexpr double kEnergyRounding = 1e-13;

}  // namespace dinam
