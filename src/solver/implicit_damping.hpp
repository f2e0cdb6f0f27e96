#pragma once
// The numerical damping of the implicit integrator's schemes on a mode of frequency ω, from their
// closed forms on a linear oscillator: in the mode's coordinate u = q − i q̇/ω a step of h
// multiplies u by backward Euler's root 1/(1 − iωh), or, once its start has died out, by BDF2's
// principal root (2 + √(1 + 2iωh))/(3 − 2iωh). The amplitude falls by the root's modulus a step.
// (tests/solver/implicit_damping_test.cpp measures both on a vibrating cantilever.)
#include "scene/scene_description.hpp"

namespace dinam {

// The share of its amplitude a mode keeps over one period resolved by `steps_per_period` steps.
double amplitude_kept_per_period(ImplicitScheme scheme, double steps_per_period);

}  // namespace dinam
